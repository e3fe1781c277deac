#include "liggghts/liggghts_materials.hpp"

#include <cstdio>
#include <stdexcept>

namespace centrec::liggghts {

namespace {
// One per-type-pair property over types (1 particle, 2 wall), row-major; wall-wall never
// meets, so it takes the particle-wall value.
std::string pair_property(int& fix, const char* property, double pp, double pw) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "fix m%d all property/global %s peratomtypepair 2 %.9g %.9g %.9g %.9g\n", fix++,
                property, pp, pw, pw, pw);
  return buf;
}
}  // namespace

std::string liggghts_rolling_keyword(const dem::RollingModel model) {
  const dem::RollingModelInfo& i = dem::rolling_model_info(model);
  if (!i.liggghts)
    throw std::invalid_argument(std::string("rolling_model: ") + i.name + " - LIGGGHTS 3.8 has no " + i.name +
                                " rolling model (its rolling_friction offers " + liggghts_rolling_models() +
                                "); choose one of those or run on the native engine");
  return i.liggghts;
}

std::string liggghts_rolling_models() {
  std::string s;
  for (const dem::RollingModelInfo& i : dem::kRollingModels)
    if (i.liggghts) s += (s.empty() ? "" : ", ") + std::string(i.liggghts);
  return s;
}

std::string liggghts_material_commands(const LiggghtsMaterials& m) {
  const LiggghtsContactPair& pp = m.particle_particle;
  const LiggghtsContactPair& pw = m.particle_wall;
  const std::string contact_model = liggghts_contact_model(pp);
  liggghts_contact_model(pw);  // refuses a wall model LIGGGHTS lacks before any text
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "fix m1 all property/global youngsModulus peratomtype %.9g %.9g\n"
                "fix m2 all property/global poissonsRatio peratomtype %.9g %.9g\n",
                m.particle_youngs_modulus, m.wall_youngs_modulus, m.particle_poisson_ratio, m.wall_poisson_ratio);
  std::string s = buf;
  int fix = 3;
  // The pair fields (dem/material.hpp for_each_pair_field), then the rolling model's own
  // coefficients (dem/rolling_models.hpp), each as its LIGGGHTS property.
  dem::for_each_pair_field(
      [&](const char*, auto f, double, double, bool, const char* property) {
        s += pair_property(fix, property, pp.*f, pw.*f);
      },
      [&](const char*, auto model, auto coefficients) {
        dem::for_each_rolling_coefficient(pp.*model, [&](std::size_t k, const dem::RollingCoefficient& c) {
          if (pw.*model != pp.*model)
            throw std::invalid_argument(std::string("rolling_model: LIGGGHTS 3.8 sets ") + c.liggghts +
                                        " for every type pair; give particle_particle and particle_wall one model");
          s += pair_property(fix, c.liggghts, (pp.*coefficients)[k], (pw.*coefficients)[k]);
        });
      });
  s += "pair_style gran " + contact_model + "\npair_coeff * *\n";
  return s;
}

}  // namespace centrec::liggghts
