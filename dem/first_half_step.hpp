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

// How far the particles may still move before the neighbour list can miss a contact.
// Each particle has a half-skin h_i, set at each build (Simulation::rebuild): a pair is
// listed when its gap is below h_i + h_j. Its gap then closes by at most the sum of the
// two displacements d_i + d_j, so the list holds while every pair keeps
// (h_i - d_i) + (h_j - d_j) >= 0: while the two smallest slacks h - d add up to no less
// than zero. Walls are taken as candidates within 2 h_i of a particle, so each particle
// also keeps 2 h_i - d_i >= 0. With one half-skin for all (skin/2) that is the rule "the
// two largest displacements within a skin", of which "any particle within skin/2" is the
// case where the two are equal (docs/dem_physics.md "Neighbour search").
struct ListSlack {
  double first = std::numeric_limits<double>::infinity();   // m, the smallest h - d
  double second = std::numeric_limits<double>::infinity();  // m, the next
  double wall = std::numeric_limits<double>::infinity();    // m, the smallest 2 h - d

  // d2: the particle's squared displacement since the build (infinity if not a number).
  void add(double d2, double half_skin) {
    const double d = std::sqrt(d2);
    const double s = half_skin - d;
    if (s < first) {
      second = first;
      first = s;
    } else if (s < second) {
      second = s;
    }
    wall = std::min(wall, 2.0 * half_skin - d);
  }
  void add(const ListSlack& o) {
    for (const double s : {o.first, o.second}) {
      if (s < first) {
        second = first;
        first = s;
      } else if (s < second) {
        second = s;
      }
    }
    wall = std::min(wall, o.wall);
  }
  // True once some pair or wall contact may be missing from the lists (also for a
  // non-finite displacement).
  bool exhausted() const { return !(first + second >= 0.0 && wall >= 0.0); }
};

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
