#pragma once
// The benchmark case: the paper's particles (source-paper Table 1) as a
// dense film on the inside of the D12 drum, axially periodic, gravity tilted 45 deg from
// the drum axis. One struct so both engines are fed from the same numbers.
#include <cmath>

#include "dem/material.hpp"

namespace centrec::bench {

struct FilmCase {
  // Drum D12 (paper case): D = 0.12 m, 160.08 rpm, axis on z, rotation right-handed about +z.
  double drum_radius = 0.06;                            // m
  double rpm = 160.08;
  // Gravity g (0, -cos 45, +sin 45): the drum axis tilted 45 deg from horizontal, the
  // film draining towards +z. Periodic in z, so the sign only sets the flow direction.
  double gravity = 9.81;                                // m/s^2
  double tilt_deg = 45.0;
  // Particles (Table 1).
  double diameter = 1.2e-3;                             // m
  double density = 3560.0;                              // kg/m^3
  double youngs_modulus = 5e6;                          // Pa (walls the same)
  double poisson_ratio = 0.3;                           // (walls the same)
  double restitution = 0.46;                            // particle-particle and -wall
  double friction = 0.81;                               // particle-particle
  double rolling_friction = 0.26;                       // particle-particle
  double wall_friction = 10000.0;                       // paper: the first layer sticks
  double wall_rolling_friction = 0.26;
  // Rolling model of both contacts and its own coefficients (dem/rolling_models.hpp).
  dem::RollingModel rolling_model = dem::RollingModel::epsd2;
  dem::RollingCoefficients rolling_coefficients{};
  double dt = 1e-5;                                     // s
  // Film: packed layers (about 4.5 d thick); N is set by the number of axial rows.
  int layers = 5;

  dem::PairInteraction pair_interaction() const {
    return {restitution, friction, rolling_friction, rolling_model, rolling_coefficients};
  }
  dem::PairInteraction wall_interaction() const {
    return {restitution, wall_friction, wall_rolling_friction, rolling_model, rolling_coefficients};
  }
  double omega() const { return rpm * 2.0 * M_PI / 60.0; }  // rad/s
  double radius() const { return 0.5 * diameter; }
  double gravity_y() const { return -gravity * std::cos(tilt_deg * M_PI / 180.0); }
  double gravity_z() const { return gravity * std::sin(tilt_deg * M_PI / 180.0); }
};

}  // namespace centrec::bench
