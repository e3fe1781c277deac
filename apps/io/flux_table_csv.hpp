#pragma once
// Reads a solar flux table for thermal::FluxProfile: CSV with two columns, z in m and q in
// W/m2, one row per line; '#' comments and one header line of text are allowed (the rows read
// by thermal/table_csv.hpp, the table's own checks here).
#include <string>
#include <vector>

namespace centrec::io {

// Throws std::runtime_error naming the file and line of the first bad row.
void read_flux_table_csv(const std::string& path, std::vector<double>& z, std::vector<double>& q);

}  // namespace centrec::io
