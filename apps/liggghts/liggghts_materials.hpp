#pragma once
// The LIGGGHTS 3.8 material and contact-law commands shared by the exported deck and
// the benchmark deck: two atom types (1 = particles, 2 = walls), per-type E and nu,
// per-type-pair e, mu and mu_r, Hertz + tangential history + EPSD2 rolling friction
// (the native engine's law, docs/dem_physics.md).
#include <string>

namespace centrec::liggghts {

struct LiggghtsContactPair {
  double restitution = 0.0, friction = 0.0, rolling_friction = 0.0;
};

struct LiggghtsMaterials {
  double particle_youngs_modulus = 0.0, wall_youngs_modulus = 0.0;  // Pa
  double particle_poisson_ratio = 0.0, wall_poisson_ratio = 0.0;
  LiggghtsContactPair particle_particle, particle_wall;
};

// "fix m1..m5 property/global ..." then the pair_style and pair_coeff lines.
std::string liggghts_material_commands(const LiggghtsMaterials& m);

// The wall/gran model arguments matching the pair style.
inline const char* liggghts_wall_model() { return "model hertz tangential history rolling_friction epsd2"; }

}  // namespace centrec::liggghts
