#pragma once
// Time-step advisor (docs/dem_physics.md): Rayleigh time and Hertz contact time, the
// default dt and the stability bound a user dt must respect.
#include <string>

#include "dem/material.hpp"

namespace centrec::dem {

// Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)).
double rayleigh_time(const Material& m, double radius);

// Hertz contact duration at impact speed v: t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5).
double hertz_contact_time(double m_eff, double r_eff, double E_eff, double v);

// Maximum Hertz overlap at impact speed v: (15 m* v^2 / (16 E* sqrt(R*)))^(2/5).
double hertz_max_overlap(double m_eff, double r_eff, double E_eff, double v);

struct TimeStepAdvice {
  double rayleigh_time = 0.0;      // smallest over particle materials/radii, s
  double hertz_time = 0.0;         // smallest over particle-particle and particle-wall pairs, s
  double max_impact_speed = 0.0;   // m/s, the speed hertz_time was evaluated at
  double stable_bound = 0.0;       // a user dt above this is refused, s
  double recommended = 0.0;        // default dt, s
  // The bound: dt <= kRayleighBound * rayleigh_time and dt <= kHertzBound * hertz_time,
  // i.e. at least 5 steps per fastest collision (velocity Verlet on a contact of
  // angular frequency pi/t_c is stable below 2 t_c/pi = 0.64 t_c; the margin covers
  // the stiffening Hertz spring) and half the Rayleigh time (dense-pack wave speed).
  static constexpr double kRayleighBound = 0.5;
  static constexpr double kHertzBound = 0.2;
  std::string report() const;  // one human-readable line
};

}  // namespace centrec::dem
