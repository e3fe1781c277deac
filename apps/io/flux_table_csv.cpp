#include "io/flux_table_csv.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace centrec::io {

void read_flux_table_csv(const std::string& path, std::vector<double>& z, std::vector<double>& q) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the flux table");
  z.clear();
  q.clear();
  std::string line;
  int lineno = 0;
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
    z.push_back(a);
    q.push_back(b);
  }
  if (z.size() < 2) throw std::runtime_error(path + ": a flux table needs at least two rows");
}

}  // namespace centrec::io
