#pragma once
// The film field (docs/coupling.md) in HDF5: group (default /film) with datasets z, eta,
// t (1D) and u, phi, D and optional u_std, phi_std, D_std ([nz, neta]), units as
// attributes, and the case metadata as number/string attributes of the group.
#include <string>

#include "io/h5_file.hpp"
#include "thermal/film_field.hpp"

namespace centrec::io {

void write_film_field(H5File& file, const thermal::FilmField& f, const std::string& group = "/film");
// Throws std::runtime_error naming the file, group and missing/inconsistent item.
thermal::FilmField read_film_field(const H5File& file, const std::string& group = "/film");

}  // namespace centrec::io
