#include "cavity_convection.hpp"

#include <algorithm>
#include <cmath>

#include "air_conductivity.hpp"

namespace centrec::thermal {

double air_kinematic_viscosity(double T) {
  const double mu = 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4);
  const double rho = 101325.0 / (287.05 * T);
  return mu / rho;
}

double cavity_convection_coefficient(double Tw, double Ti, double L, double d_ap, double tilt) {
  const double c = std::cos(tilt);
  if (!(Tw > Ti) || !(c > 0.0)) return 0.0;
  const double nu = air_kinematic_viscosity(Ti);
  const double Gr = 9.80665 * (Tw - Ti) * L * L * L / (Ti * nu * nu);
  const double ratio = std::min(1.0, d_ap / L);
  const double s = 1.12 - 0.982 * ratio;
  const double Nu = 0.088 * std::cbrt(Gr) * std::pow(Tw / Ti, 0.18) * std::pow(c, 2.47) * std::pow(ratio, s);
  return Nu * air_conductivity(Ti) / L;
}

}  // namespace centrec::thermal
