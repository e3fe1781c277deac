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

double cavity_grashof(double Tw, double Ti, double L) {
  if (!(Tw > Ti)) return 0.0;
  const double nu = air_kinematic_viscosity(Ti);
  return 9.80665 * (Tw - Ti) * L * L * L / (Ti * nu * nu);
}

double cavity_convection_coefficient(double Tw, double Ti, double L, double d_ap, double tilt) {
  const double c = std::cos(tilt);
  if (!(Tw > Ti) || !(c > 0.0)) return 0.0;
  const double Gr = cavity_grashof(Tw, Ti, L);
  const double ratio = std::min(1.0, d_ap / L);
  const double s = 1.12 - 0.982 * ratio;
  const double Nu = 0.088 * std::cbrt(Gr) * std::pow(Tw / Ti, 0.18) * std::pow(c, 2.47) * std::pow(ratio, s);
  return Nu * air_conductivity(Ti) / L;
}

double wind_convection_coefficient(double V) { return V > 0.0 ? 0.1967 * std::pow(V, 1.849) : 0.0; }

double rotation_convection_coefficient(double omega, double D, double Tw, double Ti, double* Re_r) {
  const double T_film = 0.5 * (Tw + Ti);
  const double Re = std::abs(omega) * D * D / air_kinematic_viscosity(T_film);
  if (Re_r) *Re_r = Re;
  if (!(Re > 0.0)) return 0.0;
  return 8.5101e-6 * std::pow(Re, 1.4513) * air_conductivity(T_film) / D;
}

double mixed_convection(double hn, double hw, double hr, double n) {
  const int parts = (hn > 0) + (hw > 0) + (hr > 0);
  if (parts == 0) return 0.0;
  if (parts == 1) return std::max({hn, hw, hr});
  double s = 0.0;
  for (double h : {hn, hw, hr})
    if (h > 0) s += std::pow(h, n);
  return std::pow(s, 1.0 / n);
}

CavityConvection cavity_mixed_convection(double Tw, double Ti, double D, double d_ap, double tilt, double V,
                                         double omega, double n) {
  CavityConvection c;
  c.h_natural = cavity_convection_coefficient(Tw, Ti, D, d_ap, tilt);
  c.Gr = cavity_grashof(Tw, Ti, D);
  c.h_wind = wind_convection_coefficient(V);
  c.Re_wind = V * d_ap / air_kinematic_viscosity(Ti);
  c.h_rotation = rotation_convection_coefficient(omega, D, Tw, Ti, &c.Re_rotation);
  c.h = mixed_convection(c.h_natural, c.h_wind, c.h_rotation, n);
  return c;
}

}  // namespace centrec::thermal
