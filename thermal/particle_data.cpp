#include "particle_data.hpp"

#include <stdexcept>

namespace centrec::thermal {

namespace {
// The CARBO HSP values and their ranges (docs/particle_data.md gives the full citations and
// what was searched for and not found).
constexpr RangedValue kCpScale{1.0, 0.915, 1.085,
                               "Siegel et al. 2010 power law (SolarTherm CarboHSP); range: SolarTherm's second "
                               "CARBO HSP fit lies 6.1-8.4 % below it over 600-900 C: +-8.5 %"};
constexpr RangedValue kKs{2.0, 1.0, 3.0, "SolarTherm CarboHSP (constant, unsourced there); range assumed"};
constexpr RangedValue kAlpha{0.92, 0.90, 0.95,
                             "Siegel et al. 2015: as received > 0.90, degrading in air above 700 C, > 0.95 reduced"};
constexpr RangedValue kEpsilon{0.86, 0.80, 0.90,
                               "SolarTherm particle-receiver models (0.86, 0.90); lower bound assumed"};
}  // namespace

const std::vector<ParticleData>& particle_table() {
  static const std::vector<ParticleData> table = {
      {"sg_bauxite",
       "the paper's sintered bauxite SG 16/30 (1.2 mm, 3560 kg/m3, paper Table 1); no thermal data for it was "
       "found: the CARBO HSP values stand in (same material class)",
       PowerLawCp{}, kCpScale, kKs, kAlpha, kEpsilon},
      {"carbo_hsp", "CARBO HSP sintered bauxite (SolarTherm's CarboHSP medium; Siegel et al. 2010, 2015)",
       PowerLawCp{}, kCpScale, kKs, kAlpha, kEpsilon},
  };
  return table;
}

const ParticleData& particle_data(const std::string& name) {
  std::string known;
  for (const ParticleData& p : particle_table()) {
    if (name == p.name) return p;
    known += (known.empty() ? "" : ", ") + std::string(p.name);
  }
  throw std::invalid_argument("unknown particle '" + name + "' (known: " + known + ")");
}

void apply_particle(const ParticleData& p, Material& m, HeatCapacity& h) {
  m.k_s = p.k_s.nominal;
  m.alpha = p.alpha.nominal;
  m.epsilon = p.epsilon.nominal;
  h.power_law = p.cp;
  h.scale = p.cp_scale.nominal;
}

}  // namespace centrec::thermal
