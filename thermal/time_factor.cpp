#include "time_factor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::thermal {

namespace {
// 0 before t0, 1 after t0 + ramp, linear in between.
double edge(double t, double t0, double ramp) {
  if (t <= t0) return 0.0;
  if (ramp <= 0.0 || t >= t0 + ramp) return 1.0;
  return (t - t0) / ramp;
}

double table_at(const std::vector<double>& ts, const std::vector<double>& fs, double t) {
  if (t <= ts.front()) return fs.front();
  if (t >= ts.back()) return fs.back();
  const std::size_t k = std::upper_bound(ts.begin(), ts.end(), t) - ts.begin();  // ts[k-1] <= t < ts[k]
  const double w = (t - ts[k - 1]) / (ts[k] - ts[k - 1]);
  return fs[k - 1] + w * (fs[k] - fs[k - 1]);
}
}  // namespace

double TimeFactor::at(double t) const {
  switch (kind) {
    case Kind::constant:
      return level;
    case Kind::step:
      return 1.0 + (level - 1.0) * edge(t, t_start, ramp);
    case Kind::pulse:
      return 1.0 + (level - 1.0) * (edge(t, t_start, ramp) - edge(t, t_end, ramp));
    case Kind::table:
      return table_at(table_t, table_f, t);
    case Kind::lag:
      if (t <= t_start) return from;
      if (tau <= 0.0) return level;
      return level + (from - level) * std::exp(-(t - t_start) / tau);
  }
  return 1.0;
}

std::vector<double> TimeFactor::breakpoints() const {
  switch (kind) {
    case Kind::constant:
      return {};
    case Kind::step:
      return {t_start, t_start + ramp};
    case Kind::pulse: {
      std::vector<double> b = {t_start, t_start + ramp, t_end, t_end + ramp};
      std::sort(b.begin(), b.end());
      return b;
    }
    case Kind::table:
      return table_t;
    case Kind::lag:
      return {t_start};
  }
  return {};
}

void TimeFactor::check() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("time factor: " + what); };
  if (!(ramp >= 0.0) || !(tau >= 0.0)) fail("ramp and tau must be >= 0 s");
  if (kind == Kind::table) {
    if (table_t.size() < 2 || table_t.size() != table_f.size())
      fail("a table needs at least two (t, f) points of equal count");
    for (std::size_t i = 0; i < table_t.size(); ++i) {
      const std::string row = " (point " + std::to_string(i + 1) + ")";
      if (!std::isfinite(table_t[i]) || !std::isfinite(table_f[i])) fail("table values must be finite" + row);
      if (table_f[i] < 0.0) fail("table factor must be >= 0" + row);
      if (i > 0 && !(table_t[i] > table_t[i - 1])) fail("table times must increase strictly" + row);
    }
  }
  if (kind != Kind::table && !(level >= 0.0 && std::isfinite(level))) fail("level must be finite and >= 0");
  if (kind == Kind::lag && !(from >= 0.0 && std::isfinite(from))) fail("from must be finite and >= 0");
}

}  // namespace centrec::thermal
