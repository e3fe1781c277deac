#include "film_thickness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace centrec::film {

namespace {
void check(const FilmThicknessParams& p) {
  if (!(p.cavity_diameter > 0.0) || !(p.section_length > 0.0) || !(p.particle_diameter > 0.0))
    throw std::invalid_argument("film_thickness: D, l_sec and d must be positive");
  if (!(p.solid_fraction >= 0.0 && p.solid_fraction < 1.0))
    throw std::invalid_argument("film_thickness: solid fraction must be in [0, 1)");
  if (!(p.arc_fraction > 0.0 && p.arc_fraction <= 1.0))
    throw std::invalid_argument("film_thickness: arc fraction must be in (0, 1]");
}
}  // namespace

std::size_t surface_particle_count(double t, const FilmThicknessParams& p) {
  const double d = p.particle_diameter;
  const double a_surf = p.arc_fraction * p.section_length * M_PI * (p.cavity_diameter - 2.0 * t);  // eq (4)
  const double v_p = M_PI * d * d * d / 6.0;
  const double n_p = a_surf * d * (1.0 - p.solid_fraction) / v_p;                              // eq (5)
  return n_p < 1.5 ? 1 : static_cast<std::size_t>(std::lround(n_p));
}

FilmThicknessResult film_thickness_sorted(const double* r_sorted, std::size_t n, const FilmThicknessParams& p) {
  check(p);
  FilmThicknessResult res;
  if (n == 0) {
    res.underfilled = true;
    res.converged = true;
    return res;
  }
  // Prefix sums make each evaluation of eq (7) O(1).
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + r_sorted[i];

  double t = 0.0;  // the paper's initial guess
  std::size_t last_np = 0;
  for (int it = 1; it <= p.max_iterations; ++it) {
    std::size_t np = surface_particle_count(t, p);
    res.underfilled = np > n;
    np = std::min(np, n);
    // eq (7): cavity radius minus the mean radial position of the n_p innermost centres,
    // plus a particle radius (thickness reaches the cap of the surface particles).
    t = 0.5 * p.cavity_diameter - prefix[np] / static_cast<double>(np) + 0.5 * p.particle_diameter;
    res.thickness = t;
    res.n_surface = np;
    res.iterations = it;
    if (np == last_np) {
      res.converged = true;
      break;
    }
    last_np = np;
  }
  return res;
}

FilmThicknessResult film_thickness(const double* r, std::size_t n, const FilmThicknessParams& p) {
  std::vector<double> s(r, r + n);
  std::sort(s.begin(), s.end());
  return film_thickness_sorted(s.data(), n, p);
}

}  // namespace centrec::film
