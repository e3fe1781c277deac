#include "circumferential_flux.hpp"

#include <cmath>

namespace centrec::thermal {

double surface_ripple_amplitude(double q_amplitude, double k, double rho_c, double omega) {
  return q_amplitude / std::sqrt(k * rho_c * omega);
}

double ripple_t4_excess(double T, double theta) {
  const double t2 = theta * theta;
  return 3.0 * T * T * t2 + 0.375 * t2 * t2;
}

}  // namespace centrec::thermal
