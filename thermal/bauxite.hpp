#pragma once
// Sintered bauxite (CARBO HSP) specific heat, docs/thermal_model.md ("Material properties"):
// the power law c_p = a T^b and its exact enthalpy integral and inverse. The default
// coefficients are the CARBO HSP correlation; thermal/particle_data.hpp names the particles
// that use it.

namespace centrec::thermal {

// c_p(T) = a T^b J/(kg K), T in K; h(T) = a T^(b+1) / (b+1) from 0 K, inverted exactly, so
// energy balances and the mixing-cup temperature are exact for the power law.
struct PowerLawCp {
  double a = 148.2;   // J/(kg K^(1+b))
  double b = 0.3093;  // -

  double cp(double T_kelvin) const;
  double enthalpy_rise(double T0_kelvin, double T1_kelvin) const;
  // The T (K) with enthalpy_rise(0, T) = h (J/kg).
  double temperature_at_enthalpy(double h) const;
};

// Specific heat c_p(T) = 148.2 T^0.3093 J/(kg K), T in K (Siegel et al. 2010, J. Sol.
// Energy Eng. 132, 021008, as coded in SolarTherm's CarboHSP medium; valid 50-1100 C).
double bauxite_cp(double T_kelvin);

// Enthalpy rise integral of c_p from T0 to T1 (J/kg), exact for the power law.
double bauxite_enthalpy_rise(double T0_kelvin, double T1_kelvin);

// Inverse of the enthalpy integral from 0 K: the T (K) with
// bauxite_enthalpy_rise(0, T) = h (J/kg), exact for the power law.
double bauxite_temperature_at_enthalpy(double h);

}  // namespace centrec::thermal
