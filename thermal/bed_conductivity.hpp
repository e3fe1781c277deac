#pragma once
// Effective conductivity of a packed bed of spheres without flow: Zehner-Bauer-Schluender
// model with the radiation term, in the VDI Heat Atlas form (chapter D6.3), docs/thermal_model.md. The gas is air at 1 bar; the Smoluchowski (rarefaction) correction is
// neglected because the modified free path (< 1 um) is tiny against mm particles.

namespace centrec::thermal {

struct BedConductivityParts {
  double k_bed = 0.0;  // total bed conductivity, W/(m K)
  double k_rad = 0.0;  // radiative conductivity of the voids, 4 sigma T^3 d/(2/eps - 1)
  double k_gas = 0.0;  // gas conductivity used
};

struct BedConductivityModel {
  double k_s = 2.0;               // solid conductivity, W/(m K)
  double epsilon = 0.86;          // particle emissivity
  double d = 1.2e-3;              // particle diameter, m
  double shape_factor = 1.25;     // C_f, 1.25 for spheres
  double flattening = 0.0077;     // contact flattening coefficient (VDI: 0.0077 for spheres)
  bool radiation = true;          // false drops k_rad (to split k_eff into its parts)

  // Bed conductivity at temperature T (K) and solid volume fraction phi (0 < phi < 1).
  BedConductivityParts evaluate(double T, double phi) const;
  double k_bed(double T, double phi) const { return evaluate(T, phi).k_bed; }
};

}  // namespace centrec::thermal
