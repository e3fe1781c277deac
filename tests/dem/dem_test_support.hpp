#pragma once
// Shared set-ups of the DEM tests: the paper's particle (Table 1) and small helpers.
#include <cmath>

#include "dem/simulation.hpp"
#include "dem/timestep_advisor.hpp"

namespace centrec::dem::testing {

constexpr double kRadius = 0.6e-3;  // paper Table 1: d = 1.2 mm

inline Material paper_material() { return Material{5e6, 0.3, 3560.0}; }

inline double sphere_mass(double r, double rho = 3560.0) { return rho * 4.0 / 3.0 * M_PI * r * r * r; }

// A simulation without gravity printing nothing; add a material before any particle.
inline SimulationConfig quiet_config(double dt, Vec3 gravity = {0, 0, 0}) {
  SimulationConfig c;
  c.dt = dt;
  c.gravity = gravity;
  c.verbose = false;
  return c;
}

// Adds the paper's material with the given interaction with itself (tests whose walls are
// made of it too use the same interaction for walls).
inline MaterialId use_paper_material(Simulation& sim, const PairInteraction& p) {
  const MaterialId m = sim.add_material(paper_material());
  sim.set_interaction(m, m, p);
  return m;
}

// Hertz contact time for two paper particles (or particle-wall: wall = true) at relative speed v.
inline double paper_contact_time(double v, bool wall) {
  const Material m = paper_material();
  const double E = 1.0 / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus);
  const double mass = sphere_mass(kRadius);
  return wall ? hertz_contact_time(mass, kRadius, E, v) : hertz_contact_time(0.5 * mass, 0.5 * kRadius, E, v);
}

}  // namespace centrec::dem::testing
