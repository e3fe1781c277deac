#include "io/flux_table_csv.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace centrec::io {

namespace {
// The bound of the case's flux keys on the film (apps/config/case_thermal.cpp), W/m2.
constexpr double kMaxFlux = 2e7;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
}  // namespace

void read_flux_table_csv(const std::string& path, std::vector<double>& z, std::vector<double>& q) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the flux table");
  z.clear();
  q.clear();
  std::string line;
  int lineno = 0;
  int last_line = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++lineno;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const char* s = line.c_str() + first;
    char* end = nullptr;
    const double a = std::strtod(s, &end);
    if (end == s) {
      if (header_allowed) {  // a text header such as "z_m,q_W_m2"
        header_allowed = false;
        continue;
      }
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": expected 'z_m, q_W_m2' numbers");
    }
    header_allowed = false;
    while (*end == ' ' || *end == '\t') ++end;
    if (*end != ',') throw std::runtime_error(path + ":" + std::to_string(lineno) + ": expected a comma after z");
    const char* s2 = end + 1;
    const double b = std::strtod(s2, &end);
    if (end == s2) throw std::runtime_error(path + ":" + std::to_string(lineno) + ": expected q (W/m2) after the comma");
    while (*end == ' ' || *end == '\t' || *end == '\r') ++end;
    if (*end != '\0' && *end != '#')
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": text after q ('" + std::string(end) +
                               "'); a row is two numbers: z in m, q in W/m2");
    const std::string at = path + ":" + std::to_string(lineno) + ": ";
    if (!std::isfinite(a) || !std::isfinite(b)) throw std::runtime_error(at + "z or q is not a finite number");
    if (b < 0.0) throw std::runtime_error(at + "q = " + number(b) + " W/m2 is negative");
    if (b > kMaxFlux)
      throw std::runtime_error(at + "q = " + number(b) +
                               " W/m2 is above 2e7 W/m2, the largest flux on the film the case keys accept");
    if (!z.empty() && !(a > z.back()))
      throw std::runtime_error(at + "z = " + number(a) + " m does not increase (the row before it, line " +
                               std::to_string(last_line) + ", has z = " + number(z.back()) + " m)");
    z.push_back(a);
    q.push_back(b);
    last_line = lineno;
  }
  if (z.size() < 2) throw std::runtime_error(path + ": a flux table needs at least two rows");
  // z runs along the film from its start (docs/case_keys.md): a table that ends before it
  // would hand the whole film its last row's flux.
  if (!(z.back() > 0.0))
    throw std::runtime_error(path + ":" + std::to_string(last_line) + ": the table ends at z = " +
                             number(z.back()) + " m, before the film starts (z = 0)");
}

}  // namespace centrec::io
