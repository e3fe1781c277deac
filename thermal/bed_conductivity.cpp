#include "bed_conductivity.hpp"

#include <cmath>

#include "air_conductivity.hpp"
#include "physical_constants.hpp"

namespace centrec::thermal {

BedConductivityParts BedConductivityModel::evaluate(double T, double phi) const {
  // VDI Heat Atlas D6.3 (Tsotsas), with kappa_G = 1 (no Smoluchowski effect):
  //   k_bed/k_g = (1 - sqrt(1-psi)) psi [1/psi + kappa_r]
  //             + sqrt(1-psi) [f kappa_p + (1-f) kappa_c]
  // psi = porosity = 1 - phi, f the flattening coefficient, kappa_p = k_s/k_g,
  // kappa_r = k_rad/k_g, B = C_f ((1-psi)/psi)^(10/9) and the core of the unit cell
  //   kappa_c = 2/N { B (kappa_p + kappa_r - 1)/(N^2 kappa_p) ln[(kappa_p + kappa_r)/B]
  //                   + (B+1)/(2B) [kappa_r - B] - (B-1)/N },
  //   N = 1 + (kappa_r - B)/kappa_p.
  const double Tpos = std::max(T, 1.0);
  const double psi = 1.0 - phi;
  const double kg = air_conductivity(Tpos);
  const double k_rad = !radiation ? 0.0 : 4.0 * kStefanBoltzmann * Tpos * Tpos * Tpos * d / (2.0 / epsilon - 1.0);
  const double kp = k_s / kg;
  const double kr = k_rad / kg;
  const double B = shape_factor * std::pow(phi / psi, 10.0 / 9.0);
  const double N = 1.0 + (kr - B) / kp;
  const double kc = 2.0 / N *
                    (B * (kp + kr - 1.0) / (N * N * kp) * std::log((kp + kr) / B) +
                     (B + 1.0) / (2.0 * B) * (kr - B) - (B - 1.0) / N);
  const double s = std::sqrt(1.0 - psi);
  const double ratio = (1.0 - s) * psi * (1.0 / psi + kr) + s * (flattening * kp + (1.0 - flattening) * kc);
  return {ratio * kg, k_rad, kg};
}

}  // namespace centrec::thermal
