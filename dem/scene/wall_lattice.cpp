#include "dem/scene/wall_lattice.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::dem::scene {

std::vector<Vec3> rough_wall_centres(const RoughWallSpec& spec, double R, double z0, double z1, bool periodic) {
  const double a = spec.spacing, dg = spec.sphere_diameter;
  if (!(dg > 0.0) || !(a >= dg * (1.0 - 1e-9)))
    throw std::invalid_argument("rough_wall: spacing must be at least the glued sphere diameter (no overlap)");
  const double rc = R - 0.5 * dg;
  // Count from the chord, not the arc, so neighbours on the curved wall are >= a apart.
  const int n_theta = static_cast<int>(std::floor(M_PI / std::asin(std::min(1.0, a / (2.0 * rc)))));
  if (n_theta < 3) throw std::invalid_argument("rough_wall: spacing too large for the drum");
  const double dth = 2.0 * M_PI / n_theta;
  // Hexagonal: rows a sqrt(3)/2 apart, every other row shifted by half a spacing.
  const bool hex = spec.lattice == Lattice::hexagonal;
  const double row = hex ? a * std::sqrt(3.0) / 2.0 : a;
  const double span = z1 - z0;
  int n_rows;
  double dz;
  if (periodic) {
    // Round down so rows are never closer than the lattice asks; an even count keeps
    // the hexagonal shift periodic.
    n_rows = static_cast<int>(std::floor(span / row));
    if (hex && n_rows % 2) --n_rows;
    if (n_rows < (hex ? 2 : 1)) throw std::invalid_argument("rough_wall: slice shorter than two lattice rows");
    dz = span / n_rows;
  } else {
    n_rows = static_cast<int>(std::floor((span - dg) / row)) + 1;
    dz = row;
  }
  std::vector<Vec3> c;
  c.reserve(static_cast<std::size_t>(n_rows) * n_theta);
  for (int k = 0; k < n_rows; ++k) {
    const double z = periodic ? z0 + (k + 0.5) * dz : z0 + 0.5 * dg + k * dz;
    const double shift = (hex && (k % 2)) ? 0.5 * dth : 0.0;
    for (int j = 0; j < n_theta; ++j) {
      const double th = j * dth + shift;
      c.push_back({rc * std::cos(th), rc * std::sin(th), z});
    }
  }
  return c;
}

}  // namespace centrec::dem::scene
