#pragma once
// The LIGGGHTS 3.8 material and contact-law commands shared by the exported deck and
// the benchmark deck: two atom types (1 = particles, 2 = walls), per-type E and nu,
// per-type-pair e, mu and mu_r, Hertz + tangential history + the pair's rolling model
// (the native engine's law, docs/dem_physics.md).
#include <string>

#include "dem/material.hpp"

namespace centrec::liggghts {

// The native engine's pair interaction: its fields (dem/material.hpp for_each_pair_field)
// are the per-type-pair properties and the rolling model the `rolling_friction` keyword.
using LiggghtsContactPair = dem::PairInteraction;

struct LiggghtsMaterials {
  double particle_youngs_modulus = 0.0, wall_youngs_modulus = 0.0;  // Pa
  double particle_poisson_ratio = 0.0, wall_poisson_ratio = 0.0;
  LiggghtsContactPair particle_particle, particle_wall;
};

// "fix m1..m5 property/global ..." then the pair_style and pair_coeff lines.
std::string liggghts_material_commands(const LiggghtsMaterials& m);

// The `rolling_friction` keyword of a model; throws std::invalid_argument naming the model
// when LIGGGHTS 3.8 has none (dem/rolling_models.hpp, RollingModelInfo::liggghts).
std::string liggghts_rolling_keyword(dem::RollingModel model);
// The models LIGGGHTS 3.8 has, "epsd2, cdt".
std::string liggghts_rolling_models();

// The contact model arguments of `pair_style gran` (p: particle-particle) and of a
// `fix wall/gran` (p: particle-wall).
inline std::string liggghts_contact_model(const LiggghtsContactPair& p) {
  return "model hertz tangential history rolling_friction " + liggghts_rolling_keyword(p.rolling_model);
}

}  // namespace centrec::liggghts
