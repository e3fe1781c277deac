#include "zone_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dem/film/drum_frame.hpp"

namespace centrec::film {

double MovingArc::width() const {
  const double w = wrap_angle(start - end);
  return w == 0.0 ? 2.0 * M_PI : w;
}

ZoneDetection detect_zones(const double* v, std::size_t n, double fraction) {
  if (n == 0) throw std::invalid_argument("detect_zones: no tangential bins");
  if (!(fraction > 0.0 && fraction <= 1.0)) throw std::invalid_argument("detect_zones: fraction must be in (0, 1]");
  double vmax = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (std::isfinite(v[k])) vmax = std::max(vmax, v[k]);
  if (!(vmax > 0.0)) throw std::invalid_argument("detect_zones: no bin has a positive surface velocity");

  ZoneDetection z;
  z.threshold = fraction * vmax;
  z.zone_of_bin.resize(n);
  for (std::size_t k = 0; k < n; ++k) z.zone_of_bin[k] = (std::isfinite(v[k]) && v[k] >= z.threshold) ? 1 : 0;

  const double dth = 2.0 * M_PI / n;
  auto value = [&](std::size_t k) { return std::isfinite(v[k]) ? v[k] : 0.0; };
  // Crossing between bin k and k+1 (cyclic) at the interpolated threshold.
  auto crossing = [&](std::size_t k) {
    const std::size_t k1 = (k + 1) % n;
    const double a = value(k), b = value(k1);
    const double f = (a == b) ? 0.5 : std::clamp((z.threshold - a) / (b - a), 0.0, 1.0);
    return wrap_angle((k + 0.5 + f) * dth);
  };
  // Walk up in theta: a rise (0 -> 1) is where, seen by the wall moving down in theta,
  // the film stops (`end`); a fall (1 -> 0) is where it starts.
  std::vector<double> ends, starts;
  for (std::size_t k = 0; k < n; ++k) {
    const int a = z.zone_of_bin[k], b = z.zone_of_bin[(k + 1) % n];
    if (a == 0 && b == 1) ends.push_back(crossing(k));
    if (a == 1 && b == 0) starts.push_back(crossing(k));
  }
  // Pair each end with the next start going up in theta.
  for (double e : ends) {
    MovingArc arc;
    arc.end = e;
    double best = 4.0 * M_PI;
    for (double s : starts) {
      const double gap = wrap_angle(s - e);
      if (gap < best) {
        best = gap;
        arc.start = s;
      }
    }
    z.moving.push_back(arc);
  }
  std::sort(z.moving.begin(), z.moving.end(), [](const MovingArc& x, const MovingArc& y) { return x.end < y.end; });
  return z;
}

}  // namespace centrec::film
