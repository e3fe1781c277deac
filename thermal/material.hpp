#pragma once
// Particle and bed material parameters (docs/thermal_model.md defaults: sintered bauxite,
// paper Table 1). Plain value type; the YAML reader at the edge overrides fields.

namespace centrec::thermal {

struct Material {
  double rho_s = 3560.0;   // particle (solid) density, kg/m3
  double k_s = 2.0;        // solid conductivity, W/(m K)
  double alpha = 0.92;     // solar absorptance of the film surface, -
  double epsilon = 0.86;   // thermal emissivity of particles and film surface, -
  double d = 1.2e-3;       // particle diameter, m
};

}  // namespace centrec::thermal
