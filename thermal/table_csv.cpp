#include "table_csv.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace centrec::thermal {

namespace {
std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// One field of a row: the whole of it must be a number (strtod alone accepts "1.5abc").
bool parse_field(const std::string& field, double& v) {
  const std::string f = trim(field);
  if (f.empty()) return false;
  char* end = nullptr;
  v = std::strtod(f.c_str(), &end);
  return end == f.c_str() + f.size();
}
}  // namespace

TwoColumnTable read_two_column_csv(const std::string& path, const std::string& a_name, const std::string& b_name,
                                   TableHeader header_rule) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the table");
  const std::string header = a_name + "," + b_name;
  TwoColumnTable t;
  std::string raw;
  int lineno = 0;
  bool have_header = false;
  while (std::getline(in, raw)) {
    ++lineno;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const std::string at = path + ":" + std::to_string(lineno) + ": ";
    const std::size_t comma = line.find(',');
    if (!have_header) {
      have_header = true;
      if (header_rule == TableHeader::optional) {
        double first = 0.0;
        if (!parse_field(line.substr(0, comma), first)) continue;  // a header of any text
      } else {
        // The header names the columns and their units, so a table in other units is refused.
        const bool matches = comma != std::string::npos && trim(line.substr(0, comma)) == a_name &&
                             trim(line.substr(comma + 1)) == b_name;
        if (!matches) throw std::runtime_error(at + "expected the header line '" + header + "', found '" + line + "'");
        continue;
      }
    }
    if (comma == std::string::npos)
      throw std::runtime_error(at + "expected two comma-separated numbers '" + header + "', found '" + line + "'");
    const std::string second = line.substr(comma + 1);
    if (second.find(',') != std::string::npos)
      throw std::runtime_error(at + "more than two columns; a row is '" + header + "'");
    double a = 0.0, b = 0.0;
    if (!parse_field(line.substr(0, comma), a))
      throw std::runtime_error(at + a_name + " is not a number ('" + trim(line.substr(0, comma)) + "')");
    if (!parse_field(second, b)) throw std::runtime_error(at + b_name + " is not a number ('" + trim(second) + "')");
    if (!std::isfinite(a) || !std::isfinite(b))
      throw std::runtime_error(at + a_name + " or " + b_name + " is not finite (" + number(a) + ", " + number(b) + ")");
    t.a.push_back(a);
    t.b.push_back(b);
    t.line.push_back(lineno);
  }
  t.lines = lineno;
  if (!have_header && header_rule == TableHeader::required)
    throw std::runtime_error(path + ":" + std::to_string(lineno) + ": no header line '" + header + "'");
  return t;
}

TimeFactor read_flux_time_csv(const std::string& path) {
  const TwoColumnTable t = read_two_column_csv(path, "time_s", "flux_scale");
  for (std::size_t i = 0; i < t.a.size(); ++i) {
    const std::string at = path + ":" + std::to_string(t.line[i]) + ": ";
    if (t.b[i] < 0.0) throw std::runtime_error(at + "flux_scale = " + number(t.b[i]) + " is negative");
    if (i > 0 && !(t.a[i] > t.a[i - 1]))
      throw std::runtime_error(at + "time_s = " + number(t.a[i]) + " s does not increase (line " +
                               std::to_string(t.line[i - 1]) + " has " + number(t.a[i - 1]) + " s)");
  }
  if (t.a.size() < 2) {
    throw std::runtime_error(path + ":" + std::to_string(t.lines) +
                             ": a flux time series needs at least two rows, found " + std::to_string(t.a.size()));
  }
  TimeFactor f;
  f.kind = TimeFactor::Kind::table;
  f.table_t = t.a;
  f.table_f = t.b;
  f.check();
  return f;
}

}  // namespace centrec::thermal
