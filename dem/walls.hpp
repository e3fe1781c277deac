#pragma once
// Analytic walls (docs/dem_physics.md and docs/centrec_scene.md): infinite plane, cylinder interior with an
// axial extent, and a flat disc/annulus plate (two-sided, zero thickness: back plate,
// outlet lip, annular weir of inner radius R - h). Each wall may translate (velocity) and
// spin about its own symmetry axis through `origin` (angular_velocity); the surface
// velocity velocity + angular_velocity x (p - origin) enters the contact law.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "dem/material.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

enum class WallShape : std::uint8_t { plane, cylinder, disc };

struct Wall {
  WallShape shape = WallShape::plane;
  int material = -1;     // MaterialId::index, set by the factories (add_wall refuses -1)
  Vec3 origin;           // plane: a point on it; cylinder: a point on the axis; disc: centre
  Vec3 axis{0, 0, 1};    // unit; plane: normal pointing to the particle side; else symmetry axis
  double radius = 0.0;        // cylinder radius; disc outer radius
  double inner_radius = 0.0;  // disc: hole radius (0 = full disc)
  double axial_min = -std::numeric_limits<double>::infinity();  // cylinder extent along axis,
  double axial_max = std::numeric_limits<double>::infinity();   // measured from origin
  Vec3 velocity;          // translation, m/s (moves origin each step)
  Vec3 angular_velocity;  // rad/s, must be parallel to axis (rotation keeps the geometry)

  static Wall plane(Vec3 point, Vec3 normal, MaterialId material);
  // Interior of a cylinder of radius r about the axis through origin, extent
  // [axial_min, axial_max] along the axis, spinning at omega (rad/s, right-handed about axis).
  static Wall cylinder(Vec3 origin, Vec3 axis, double r, double axial_min, double axial_max, double omega,
                       MaterialId material);
  // Flat annulus inner_r <= rho <= outer_r in the plane through centre normal to axis,
  // spinning at omega about axis. inner_r = 0 gives a full disc.
  static Wall disc(Vec3 centre, Vec3 axis, double outer_r, double inner_r, double omega, MaterialId material);
};

// Contact geometry of a sphere with a wall.
struct WallContact {
  double overlap = 0.0;  // > 0 in contact
  Vec3 n;                // unit normal from the wall to the sphere centre
  Vec3 point;            // contact point on the wall surface
};

// Distance from the sphere centre p to the wall surface along the contact normal, and
// the normal and surface point. Returns false when p is outside the wall's active region
// (beyond a cylinder's axial extent, behind a plane, exactly on a disc plane's edge).
// Inline: it runs for every candidate wall of every particle each step.
inline bool wall_geometry(const Wall& w, Vec3 p, double& distance, Vec3& n, Vec3& point) {
  const Vec3 d = p - w.origin;
  const double s = dot(d, w.axis);
  switch (w.shape) {
    case WallShape::plane: {
      if (s <= 0.0) return false;  // one-sided: behind the plane
      distance = s;
      n = w.axis;
      point = p - s * w.axis;
      return true;
    }
    case WallShape::cylinder: {
      if (s < w.axial_min || s > w.axial_max) return false;
      const Vec3 q = d - s * w.axis;
      const double rho = norm(q);
      if (rho == 0.0) return false;  // on the axis: no defined normal, and far from the wall
      const Vec3 u = (1.0 / rho) * q;
      distance = w.radius - rho;
      n = -u;
      point = w.origin + s * w.axis + w.radius * u;
      return true;
    }
    case WallShape::disc: {
      const Vec3 q = d - s * w.axis;
      const double rho = norm(q);
      // Closest point of the annulus: the in-plane radius clamped to [inner, outer]
      // (covers the flat face and both rims, e.g. the lip edge a film flows over).
      const double rc = std::clamp(rho, w.inner_radius, w.radius);
      Vec3 c = w.origin;
      if (rho > 0.0) {
        c += (rc / rho) * q;
      } else if (w.inner_radius > 0.0) {
        return false;  // on the axis of a ring: equidistant from the whole rim
      }
      const Vec3 e = p - c;
      distance = norm(e);
      if (distance == 0.0) return false;
      n = (1.0 / distance) * e;
      point = c;
      return true;
    }
  }
  return false;
}


// Surface velocity of the wall at point p.
inline Vec3 wall_velocity_at(const Wall& w, Vec3 p) { return w.velocity + cross(w.angular_velocity, p - w.origin); }

// Throws std::invalid_argument naming the bad field (non-unit axis, negative radius,
// angular velocity not along the axis, ...).
void check_wall(const Wall& w);

}  // namespace centrec::dem
