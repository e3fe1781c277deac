#include "io/flux_table_csv.hpp"

#include "thermal/table_csv.hpp"

#include <cmath>
#include <cstdio>
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
  // The rows as written (a header of any text, comments, two finite numbers per row), then what
  // a flux table along the film must be.
  const thermal::TwoColumnTable t = thermal::read_two_column_csv(path, "z_m", "q_W_m2", thermal::TableHeader::optional);
  z.clear();
  q.clear();
  for (std::size_t i = 0; i < t.a.size(); ++i) {
    const double a = t.a[i], b = t.b[i];
    const std::string at = path + ":" + std::to_string(t.line[i]) + ": ";
    if (b < 0.0) throw std::runtime_error(at + "q = " + number(b) + " W/m2 is negative");
    if (b > kMaxFlux)
      throw std::runtime_error(at + "q = " + number(b) +
                               " W/m2 is above 2e7 W/m2, the largest flux on the film the case keys accept");
    if (!z.empty() && !(a > z.back()))
      throw std::runtime_error(at + "z = " + number(a) + " m does not increase (the row before it, line " +
                               std::to_string(t.line[i - 1]) + ", has z = " + number(z.back()) + " m)");
    z.push_back(a);
    q.push_back(b);
  }
  if (z.size() < 2) throw std::runtime_error(path + ": a flux table needs at least two rows");
  // z runs along the film from its start (docs/case_keys.md): a table that ends before it
  // would hand the whole film its last row's flux.
  if (!(z.back() > 0.0))
    throw std::runtime_error(path + ":" + std::to_string(t.line.back()) + ": the table ends at z = " +
                             number(z.back()) + " m, before the film starts (z = 0)");
}

}  // namespace centrec::io
