#include "steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace centrec::film {

namespace {
// Cumulative mass of a piecewise-constant rate series, and its value at any time.
struct CumulativeMass {
  const double* t;
  std::vector<double> m;
  CumulativeMass(const double* times, const double* rate, std::size_t n) : t(times), m(n, 0.0) {
    for (std::size_t i = 1; i < n; ++i) m[i] = m[i - 1] + rate[i] * (t[i] - t[i - 1]);
  }
  double at(double time) const {
    const std::size_t n = m.size();
    const std::size_t j = std::upper_bound(t, t + n, time) - t;  // first t[j] > time
    if (j == 0) return m[0];
    if (j >= n) return m[n - 1];
    const double f = (time - t[j - 1]) / (t[j] - t[j - 1]);
    return m[j - 1] + f * (m[j] - m[j - 1]);
  }
};
}  // namespace

double turns_to_seconds(double turns, double omega) {
  if (!(omega != 0.0) || !(turns > 0.0)) throw std::invalid_argument("turns_to_seconds: need turns > 0, omega != 0");
  return turns * 2.0 * M_PI / std::fabs(omega);
}

SteadyStateResult find_steady_state(const double* t, const double* in, const double* out, std::size_t n,
                                    const SteadyStateCriterion& c) {
  if (n < 2) throw std::invalid_argument("find_steady_state: need at least two samples");
  for (std::size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1])) throw std::invalid_argument("find_steady_state: times must increase strictly");
  if (!(c.window > 0.0) || !(c.tolerance >= 0.0))
    throw std::invalid_argument("find_steady_state: window must be positive, tolerance non-negative");

  const CumulativeMass mi(t, in, n), mo(t, out, n);
  SteadyStateResult r;
  r.time = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t j = 1; j < n; ++j) {
    const double t0 = t[j] - c.window;
    if (t0 < t[0]) continue;  // the window must lie inside the series
    r.inlet_mean = (mi.m[j] - mi.at(t0)) / c.window;
    r.outlet_mean = (mo.m[j] - mo.at(t0)) / c.window;
    if (std::fabs(r.outlet_mean - r.inlet_mean) <= c.tolerance * std::fabs(r.inlet_mean)) {
      r.steady = true;
      r.time = t[j];
      return r;
    }
  }
  return r;
}

}  // namespace centrec::film
