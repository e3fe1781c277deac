#pragma once
// EPSD2 rolling resistance (docs/dem_physics.md; LIGGGHTS 3.x rolling_model_epsd2.h):
// kr = kt R*^2, elastic-plastic spring torque, no dashpot.
#include <cmath>

#include "dem/vec3.hpp"

namespace centrec::dem {

// Returns the new rolling torque Mr (the torque on i is -Mr, on j +Mr).
// w_rel: relative angular velocity (w_i - w_j; wall: see WallRolling); only its part
// tangent to the contact (perpendicular to n) loads the spring. |Mr| <= mu_r R* |Fn|.
inline Vec3 epsd2_rolling_torque(double kt, double r_eff, double mu_r, double fn, Vec3 n, Vec3 w_rel, Vec3 mr_old,
                                 double dt) {
  const Vec3 w_t = w_rel - dot(w_rel, n) * n;
  Vec3 mr = mr_old + (kt * r_eff * r_eff * dt) * w_t;
  const double mr_max = mu_r * r_eff * std::fabs(fn);
  const double mag2 = norm2(mr);
  if (mag2 > mr_max * mr_max) mr *= mr_max / std::sqrt(mag2);
  return mr;
}

}  // namespace centrec::dem
