#include "bench/film_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace centrec::bench {

FilmSummary summarize_film(const FilmCase& c, long n, const double* x, const double* v, const double* w,
                           double mass, double inertia) {
  FilmSummary s;
  s.atoms = n;
  s.min_radius = std::numeric_limits<double>::infinity();
  const double wall_r = c.drum_radius - c.radius();
  double ke = 0, rke = 0, speed = 0, omz = 0, vz = 0, wall = 0;
  for (long i = 0; i < n; ++i) {
    const double* p = x + 3 * i;
    const double* u = v + 3 * i;
    const double* o = w + 3 * i;
    const double v2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    const double r2 = p[0] * p[0] + p[1] * p[1];
    const double r = std::sqrt(r2);
    ke += 0.5 * mass * v2;
    rke += 0.5 * inertia * (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
    speed += std::sqrt(v2);
    omz += (p[0] * u[1] - p[1] * u[0]) / r2;
    vz += u[2];
    s.min_radius = std::min(s.min_radius, r);
    s.max_radius = std::max(s.max_radius, r);
    if (r > wall_r) wall += 1;
  }
  const double inv = n > 0 ? 1.0 / n : 0.0;
  s.kinetic_energy = ke;
  s.rotational_energy = rke;
  s.mean_speed = speed * inv;
  s.mean_omega_z = omz * inv;
  s.mean_vz = vz * inv;
  s.wall_contacts = wall;
  return s;
}

}  // namespace centrec::bench
