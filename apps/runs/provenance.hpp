#pragma once
// The provenance of a run's HDF5 outputs (io/provenance.hpp) from its case: the case file
// and the files the case reads (thermal.film.file, thermal.flux.table_file), hashed.
#include <string>

#include "io/provenance.hpp"

namespace centrec::runs {

io::Provenance case_provenance(const std::string& case_path, const std::string& resolved_yaml);

}  // namespace centrec::runs
