#pragma once
// Specific heat and enthalpy of the particles: the named particle's power law c_p(T)
// (thermal/bauxite.hpp, thermal/particle_data.hpp, docs/thermal_model.md) or a constant
// (analytic tests), times a scale (the error budget's perturbation of c_p). Enthalpy is the
// exact integral of c_p, so energy balances and the outlet mixing-cup temperature are exact.
#include "bauxite.hpp"

namespace centrec::thermal {

struct HeatCapacity {
  double cp_constant = 0.0;  // J/(kg K); 0 selects the power law
  PowerLawCp power_law;      // c_p(T) = a T^b (default: CARBO HSP)
  double scale = 1.0;        // multiplies c_p and h (1: the correlation as published)

  double cp(double T) const;
  // Specific enthalpy relative to 0 K (J/kg); only differences are physical.
  double enthalpy(double T) const;
  // Inverse of enthalpy(): the T with enthalpy(T) = h.
  double temperature(double h) const;
};

}  // namespace centrec::thermal
