#pragma once
// Sintered bauxite (CARBO HSP) property defaults, docs/thermal_model.md.

namespace centrec::thermal {

// Specific heat c_p(T) = 148.2 T^0.3093 J/(kg K), T in K (Siegel et al. 2010/2015;
// valid 50-1100 C).
double bauxite_cp(double T_kelvin);

// Enthalpy rise integral of c_p from T0 to T1 (J/kg), exact for the power law.
double bauxite_enthalpy_rise(double T0_kelvin, double T1_kelvin);

// Inverse of the enthalpy integral from 0 K: the T (K) with
// bauxite_enthalpy_rise(0, T) = h (J/kg), exact for the power law.
double bauxite_temperature_at_enthalpy(double h);

}  // namespace centrec::thermal
