#pragma once
// The first half of a velocity-Verlet step for one particle (LIGGGHTS nve/sphere initial
// integrate): half kick and drift of a free particle, or the exact rotation of one glued
// to the drum; then its squared displacement since the last neighbour-list build. Used by
// Simulation::integrate_first_half and by the force pass, which runs it right after the
// previous step's second half kick while the particle's data are in cache (one sweep over
// the particle arrays per step instead of three).
#include <algorithm>
#include <cmath>
#include <limits>

#include "dem/motion.hpp"
#include "dem/periodic_z.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

// Rotates u about the unit axis k by the angle whose cosine and sine are given (Rodrigues).
inline Vec3 rotate(Vec3 u, Vec3 k, double c, double s) { return c * u + s * cross(k, u) + ((1.0 - c) * dot(k, u)) * k; }

// Half kick of a free particle: v += dt/2 F/m, w += dt/2 T/I (either half of the step).
inline void half_kick(double half, double inv_m, double inv_inertia, Vec3 f, Vec3 t, Vec3& v, Vec3& w) {
  v += (half * inv_m) * f;
  w += (half * inv_inertia) * t;
}

struct FirstHalfStep {
  double dt = 0.0, half = 0.0;  // s
  DrumMotion drum;
  double c = 1.0, s = 0.0;      // cosine and sine of the drum's turn in one step
  Vec3 spin;                    // drum angular velocity vector, rad/s
  double cb = 1.0, sb = 0.0;    // of the turn since the last build (0 unless in the drum frame)
  PeriodicZ pz;

  // Advances x, v, w; returns the squared displacement from x_build, measured in the drum
  // frame (infinity if not a number: the caller then rebuilds and the force pass reports it).
  double advance(Motion motion, double inv_m, double inv_inertia, Vec3 f, Vec3 t, Vec3 x_build, Vec3& x, Vec3& v,
                 Vec3& w) const {
    if (motion == Motion::free) {
      half_kick(half, inv_m, inv_inertia, f, t, v, w);
      x += dt * v;
    } else {  // rigidly with the drum: exact rotation of the position
      const Vec3 rel = rotate(x - drum.origin, drum.axis, c, s);
      x = drum.origin + rel;
      v = cross(spin, rel);
      w = spin;
    }
    x.z = pz.wrap(x.z);
    Vec3 d = x - (drum.origin + rotate(x_build - drum.origin, drum.axis, cb, sb));
    d.z = pz.image(d.z);
    const double d2 = norm2(d);
    return d2 == d2 ? d2 : std::numeric_limits<double>::infinity();
  }
};

}  // namespace centrec::dem
