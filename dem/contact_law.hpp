#pragma once
// The one contact law used for particle-particle and particle-wall contacts
// (docs/dem_physics.md and docs/architecture.md): Hertz + Mindlin + a rolling model
// (dem/rolling_models.hpp) as a pure inline function.
// The neighbour loop, threading and history storage live elsewhere (simulation.cpp).
#include "dem/contact_history.hpp"
#include "dem/hertz_mindlin.hpp"
#include "dem/material.hpp"
#include "dem/rolling_models.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

// Plain aggregate, built in one brace-initialisation in the hot loop (no default member
// initialisers: a zero-fill then piecewise overwrite defeats store forwarding).
struct ContactInput {
  double delta;    // overlap, m (> 0 in contact)
  Vec3 n;          // unit normal from j (or the wall) to i
  Vec3 v_contact;  // velocity of i's surface relative to j's at the contact point:
                   // v_i - v_j - (arm_i w_i + arm_j w_j) x n   (wall: v_j = wall velocity there)
  Vec3 w_rel;      // relative angular velocity seen by the rolling model
  double r_eff;    // R* (wall: R_i)
  double m_eff;    // m* (wall: m_i)
  double arm_i;    // lever arm of i to the contact point: R_i - delta/2 (LIGGGHTS c_r)
  double arm_j;    // same for j (wall: 0)
};

struct ContactResult {
  Vec3 force;     // on i (on j: -force)
  Vec3 torque_i;  // on i about its centre
  Vec3 torque_j;  // on j about its centre
  double fn = 0.0;
  bool sliding = false;
  ContactHistory history;  // new history, to be stored if the step updates history
};

// The relative contact velocity as LIGGGHTS surface_model_default.h forms it.
inline Vec3 contact_velocity(Vec3 v_rel, Vec3 w_i, Vec3 w_j, double arm_i, double arm_j, Vec3 n) {
  return v_rel - cross(arm_i * w_i + arm_j * w_j, n);
}

// The input of the contact of particles a and c in canonical operand order (a the lower
// id) from their separation sd = x_a - x_c (minimum image), its length dist and the
// overlap delta = R_a + R_c - dist > 0.
inline ContactInput pair_contact_input(Vec3 sd, double dist, double delta, double ra, double rc, double ma,
                                       double mc, Vec3 va, Vec3 vc, Vec3 wa, Vec3 wc) {
  const Vec3 nrm = (1.0 / dist) * sd;
  const double arm_a = ra - 0.5 * delta, arm_c = rc - 0.5 * delta;
  return {delta, nrm,         contact_velocity(va - vc, wa, wc, arm_a, arm_c, nrm), wa - wc, ra * rc / (ra + rc),
          ma * mc / (ma + mc), arm_a, arm_c};
}

inline ContactResult evaluate_contact(const PairConstants& c, const ContactInput& in, const ContactHistory& old,
                                      double dt) {
  const HertzMindlinCoefficients k = hertz_mindlin_coefficients(c, in.delta, in.r_eff, in.m_eff);
  const double vn = dot(in.v_contact, in.n);
  const Vec3 vt = in.v_contact - vn * in.n;
  ContactResult out;
  out.fn = hertz_normal_force(k, in.delta, vn);
  const TangentialResult t = mindlin_tangential(k, c.mu, out.fn, in.n, vt, old.shear, dt, out.history.shear);
  out.sliding = t.sliding;
  RollingOut<Vec3> roll{Vec3{}, Vec3{}};
  if (c.mu_r > 0.0)
    roll = rolling_torque(c.rolling, rolling_input(k.kt, k.kn, in.delta, in.r_eff, c.mu_r, out.fn, in.n, in.w_rel,
                                                   old.roll, c.rolling_coefficients.data(), dt));
  out.history.roll = roll.history;
  out.force = out.fn * in.n + t.force;
  // Tangential force acts at the contact point: -arm_i n on i, +arm_j n on j.
  const Vec3 nxft = cross(in.n, t.force);
  out.torque_i = -in.arm_i * nxft - roll.torque;
  out.torque_j = -in.arm_j * nxft + roll.torque;
  return out;
}

}  // namespace centrec::dem
