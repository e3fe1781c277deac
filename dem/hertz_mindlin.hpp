#pragma once
// Hertz normal force with damping and Mindlin no-slip tangential force with history and
// a Coulomb cap: docs/dem_physics.md, as LIGGGHTS 3.x normal_model_hertz.h and
// tangential_model_history.h compute them.
#include <cmath>

#include "dem/material.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

// Overlap-dependent stiffnesses and dashpots of one contact.
struct HertzMindlinCoefficients {
  double kn;       // (4/3) E* sqrt(R* delta)
  double kt;       // St = 8 G* sqrt(R* delta)
  double gamma_n;  // -2 sqrt(5/6) beta sqrt(Sn m*), Sn = 2 E* sqrt(R* delta); >= 0
  double gamma_t;  // -2 sqrt(5/6) beta sqrt(St m*); >= 0
};

inline HertzMindlinCoefficients hertz_mindlin_coefficients(const PairConstants& c, double delta, double r_eff,
                                                           double m_eff) {
  const double root = std::sqrt(r_eff * delta);
  const double q = std::sqrt(root * m_eff);  // sqrt(Sn m*) = sqrt(2 E*) q (see PairConstants)
  return {(4.0 / 3.0) * c.E_eff * root, 8.0 * c.G_eff * root, c.damp_n * q, c.damp_t * q};
}

// Normal force magnitude on i along n: Fn = kn delta - gamma_n vn, with vn = v_rel.n
// (negative while approaching). May go slightly negative near separation, as in LIGGGHTS.
inline double hertz_normal_force(const HertzMindlinCoefficients& k, double delta, double vn) {
  return k.kn * delta - k.gamma_n * vn;
}

struct TangentialResult {
  Vec3 force;    // tangential force on i
  bool sliding;  // Coulomb cap active
};

// shear += vt dt, projected onto the tangent plane; Ft = -kt shear; if |Ft| > mu|Fn| scale
// Ft to mu|Fn| and set shear = -Ft/kt (no damping while sliding); else Ft -= gamma_t vt.
// The cap tests the elastic part only, so a sticking, damped contact may carry
// |Ft| > mu|Fn| (LIGGGHTS 3.8 tangential_model_history.h does the same).
// The new tangential displacement is written to `shear` (in the caller's history, so the
// result is not merged through a stack copy that stalls store forwarding).
inline TangentialResult mindlin_tangential(const HertzMindlinCoefficients& k, double mu, double fn, Vec3 n, Vec3 vt,
                                           Vec3 shear_old, double dt, Vec3& shear) {
  shear = shear_old + dt * vt;
  shear -= dot(shear, n) * n;
  Vec3 ft = -k.kt * shear;
  const double ft_max = mu * std::fabs(fn);
  const double ft2 = norm2(ft);
  if (ft2 > ft_max * ft_max) {
    ft *= ft_max / std::sqrt(ft2);
    shear = (-1.0 / k.kt) * ft;
    return {ft, true};
  }
  ft -= k.gamma_t * vt;
  return {ft, false};
}

}  // namespace centrec::dem
