#pragma once
// Two-column CSV tables for the thermal inputs: one "a,b" row per line, blank lines and '#'
// comments (whole line or after a row) skipped; the case's flux table along z
// (apps/io/flux_table_csv.hpp) is read by the same reader. The flux time series of a passing cloud,
// `time_s,flux_scale` (docs/thermal_model.md, "Solvers": transient time factors), is read
// into a table TimeFactor.
#include <string>
#include <vector>

#include "time_factor.hpp"

namespace centrec::thermal {

// The rows of a two-column table and the file line each came from.
struct TwoColumnTable {
  std::vector<double> a, b;
  std::vector<int> line;
  int lines = 0;  // lines in the file
};

// How a table's header is read: `required`, the first line that is neither blank nor a comment
// must be "a_name,b_name" (spaces around the names allowed: the names carry the units, so a
// table in other units is refused); `optional`, that first line is a header of any text when it
// does not start with a number, else already a row.
enum class TableHeader { required, optional };

// Reads `path`: after the header, every line two finite numbers. Throws std::runtime_error
// "path:line: reason" at the first bad line (a missing file, a missing or different required
// header, a field that is not a number, a third column, inf or nan).
TwoColumnTable read_two_column_csv(const std::string& path, const std::string& a_name, const std::string& b_name,
                                   TableHeader header = TableHeader::required);

// A cloud's flux scale over time, `time_s,flux_scale` (header required): times strictly
// increasing, scales >= 0, at least two rows; returned as a table TimeFactor. Throws
// std::runtime_error "path:line: reason" naming the offending row.
TimeFactor read_flux_time_csv(const std::string& path);

}  // namespace centrec::thermal
