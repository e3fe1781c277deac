#pragma once
// Named particles: the thermal and optical properties the film model takes from the particle
// (c_p(T), solid conductivity k_s, solar absorptance, thermal emissivity), each with a stated
// uncertainty range and where the value comes from (docs/particle_data.md). A case names
// its particle (`thermal.particle`); the error budget (thermal/error_budget.hpp) draws each
// property from its range. Density and diameter are not here: they are the DEM's (paper
// Table 1) and the same in both stages.
#include <string>
#include <vector>

#include "heat_capacity.hpp"
#include "material.hpp"

namespace centrec::thermal {

// A property's nominal value and the range it is known to lie in (uniform within it: no
// source gives a distribution). `source` names the publication or says "assumed".
struct RangedValue {
  double nominal = 0.0, lo = 0.0, hi = 0.0;
  const char* source = "";
};

struct ParticleData {
  const char* name;         // the case's `thermal.particle`
  const char* description;
  PowerLawCp cp;            // c_p(T) = a T^b
  RangedValue cp_scale;     // multiplies the correlation (nominal 1)
  RangedValue k_s;          // W/(m K)
  RangedValue alpha;        // solar absorptance of the film
  RangedValue epsilon;      // thermal emissivity
  // The temperatures the data hold over, K: the c_p correlation's fitted range, 50-1100 C
  // (Siegel et al. 2010 as coded in SolarTherm's CarboHSP medium, docs/particle_data.md).
  double T_min = 323.15, T_max = 1373.15;
};

// Every named particle, the default (the paper's) first.
const std::vector<ParticleData>& particle_table();
// The particle of that name; throws std::invalid_argument naming the known names.
const ParticleData& particle_data(const std::string& name);
// Copies the particle's nominal values into the material (k_s, alpha, epsilon) and the heat
// capacity (its c_p(T), scale 1); density and diameter are left as they are.
void apply_particle(const ParticleData& p, Material& m, HeatCapacity& h);

}  // namespace centrec::thermal
