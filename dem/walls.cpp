#include "walls.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace centrec::dem {

Wall Wall::plane(Vec3 point, Vec3 normal, MaterialId material) {
  Wall w;
  w.shape = WallShape::plane;
  w.origin = point;
  w.axis = normalized(normal);
  w.material = material.index;
  return w;
}

namespace {

// A wall of revolution about `axis` through `origin`, spinning at omega about that axis.
Wall revolving(WallShape shape, Vec3 origin, Vec3 axis, double r, double omega, MaterialId material) {
  Wall w;
  w.shape = shape;
  w.origin = origin;
  w.axis = normalized(axis);
  w.radius = r;
  w.angular_velocity = omega * w.axis;
  w.material = material.index;
  return w;
}

}  // namespace

Wall Wall::cylinder(Vec3 origin, Vec3 axis, double r, double axial_min, double axial_max, double omega,
                    MaterialId material) {
  Wall w = revolving(WallShape::cylinder, origin, axis, r, omega, material);
  w.axial_min = axial_min;
  w.axial_max = axial_max;
  return w;
}

Wall Wall::disc(Vec3 centre, Vec3 axis, double outer_r, double inner_r, double omega, MaterialId material) {
  Wall w = revolving(WallShape::disc, centre, axis, outer_r, omega, material);
  w.inner_radius = inner_r;
  return w;
}

void check_wall(const Wall& w) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("wall: " + what); };
  if (std::fabs(norm(w.axis) - 1.0) > 1e-9) fail("axis must be a unit vector");
  if (!is_finite(w.origin) || !is_finite(w.velocity) || !is_finite(w.angular_velocity)) fail("non-finite field");
  if (w.shape != WallShape::plane && !(w.radius > 0.0))
    fail("radius = " + std::to_string(w.radius) + " must be > 0");
  if (w.shape == WallShape::disc && !(w.inner_radius >= 0.0 && w.inner_radius < w.radius))
    fail("inner_radius = " + std::to_string(w.inner_radius) + " must lie in [0, radius)");
  if (w.shape == WallShape::cylinder && !(w.axial_min < w.axial_max)) fail("axial_min must be < axial_max");
  // Spinning about anything but the symmetry axis would move the geometry.
  if (norm(cross(w.angular_velocity, w.axis)) > 1e-12 * (1.0 + norm(w.angular_velocity)))
    fail("angular_velocity must be parallel to the axis");
  if (w.material < 0) fail("no material (build walls with Wall::plane/cylinder/disc)");
}

}  // namespace centrec::dem
