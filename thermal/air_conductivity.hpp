#pragma once
// Conductivity of air at 1 bar as a function of temperature (the interstitial gas of the
// bed; docs/thermal_model.md asks for a T-dependent gas conductivity).

namespace centrec::thermal {

// k_air(T) in W/(m K), T in K. Cubic fit to tabulated air properties, valid 100-1600 K
// (0.0263 at 300 K, 0.082 at 1273 K); clamped to that range outside it.
double air_conductivity(double T_kelvin);

}  // namespace centrec::thermal
