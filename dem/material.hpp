#pragma once
// Material and material-pair parameters of the contact law (docs/dem_physics.md).
#include <cmath>

#include "dem/rolling_models.hpp"

namespace centrec::dem {

// A material of one Simulation, as Simulation::add_material returned it. It has no
// default: every particle and wall names the material it is made of; the engine has
// no built-in material to fall back on.
struct MaterialId {
  explicit constexpr MaterialId(int i) : index(i) {}
  int index;
};

struct Material {
  double youngs_modulus = 5e6;  // Pa (paper Table 1)
  double poisson_ratio = 0.3;
  double density = 3560.0;  // kg/m^3
};

// Interaction parameters given per material pair (particle-particle, particle-wall).
// Each field is named once in for_each_pair_field below, which the engine's checks, the
// checkpoint, the case reader's comparison and the LIGGGHTS export walk.
struct PairInteraction {
  double restitution = 0.46;
  double friction = 0.81;          // sliding, Coulomb
  double rolling_friction = 0.26;  // mu_r of the rolling model
  RollingModel rolling_model = RollingModel::epsd2;
  // The rolling model's own coefficients by slot (kRollingModels[model].coefficients; zero
  // in the slots the model does not use).
  RollingCoefficients rolling_coefficients{};
};

// f(name, member pointer, lowest, highest, lowest_open, liggghts): the numeric fields with
// their ranges (restitution in (0, 1], the others >= 0) and their LIGGGHTS 3.8
// per-type-pair property; then g(name, model member, coefficients member) for the rolling
// model, whose own coefficients for_each_rolling_coefficient (dem/rolling_models.hpp) names.
template <class F, class G>
void for_each_pair_field(F&& f, G&& g) {
  f("restitution", &PairInteraction::restitution, 0.0, 1.0, true, "coefficientRestitution");
  f("friction", &PairInteraction::friction, 0.0, kInfinity, false, "coefficientFriction");
  f("rolling_friction", &PairInteraction::rolling_friction, 0.0, kInfinity, false, "coefficientRollingFriction");
  g("rolling_model", &PairInteraction::rolling_model, &PairInteraction::rolling_coefficients);
}

inline bool same(const PairInteraction& a, const PairInteraction& b) {
  bool eq = true;
  for_each_pair_field([&](const char*, auto m, double, double, bool, const char*) { eq = eq && a.*m == b.*m; },
                      [&](const char*, auto m, auto c) { eq = eq && a.*m == b.*m && a.*c == b.*c; });
  return eq;
}

// Precomputed once per material pair: effective moduli and the damping factor.
struct PairConstants {
  double E_eff = 0.0;  // E*: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
  double G_eff = 0.0;  // G*: 1/G* = 2(2-nu1)(1+nu1)/E1 + 2(2-nu2)(1+nu2)/E2
  double beta = 0.0;   // ln(e)/sqrt(ln^2(e)+pi^2), < 0 (0 for e = 1)
  double mu = 0.0;
  double mu_r = 0.0;
  RollingModel rolling = RollingModel::epsd2;
  RollingCoefficients rolling_coefficients{};  // PairInteraction's
  // Dashpot prefactors: gamma_n = damp_n sqrt(sqrt(R* delta) m*) equals
  // -2 sqrt(5/6) beta sqrt(Sn m*) with Sn = 2 E* sqrt(R* delta); damp_t likewise with
  // St = 8 G* sqrt(R* delta). Saves two square roots per contact.
  double damp_n = 0.0;  // -2 sqrt(5/6) beta sqrt(2 E*)
  double damp_t = 0.0;  // -2 sqrt(5/6) beta sqrt(8 G*)
};

PairConstants make_pair_constants(const Material& a, const Material& b, const PairInteraction& p);

}  // namespace centrec::dem
