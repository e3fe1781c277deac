#pragma once
// Specific heat and enthalpy of the particles: bauxite c_p(T) (docs/thermal_model.md) or a
// constant (analytic tests). Enthalpy is the exact integral of c_p, so energy balances and
// the outlet mixing-cup temperature are exact for the power law.

namespace centrec::thermal {

struct HeatCapacity {
  double cp_constant = 0.0;  // J/(kg K); 0 selects bauxite c_p(T)

  double cp(double T) const;
  // Specific enthalpy relative to 0 K (J/kg); only differences are physical.
  double enthalpy(double T) const;
  // Inverse of enthalpy(): the T with enthalpy(T) = h.
  double temperature(double h) const;
};

}  // namespace centrec::thermal
