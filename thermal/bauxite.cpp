#include "bauxite.hpp"

#include <algorithm>
#include <cmath>

namespace centrec::thermal {

double PowerLawCp::cp(double T) const { return a * std::pow(T, b); }

double PowerLawCp::enthalpy_rise(double T0, double T1) const {
  const double p = b + 1.0;
  return a / p * (std::pow(T1, p) - std::pow(T0, p));
}

double PowerLawCp::temperature_at_enthalpy(double h) const {
  const double p = b + 1.0;
  return std::pow(std::max(h, 0.0) * p / a, 1.0 / p);
}

double bauxite_cp(double T) { return PowerLawCp{}.cp(T); }

double bauxite_enthalpy_rise(double T0, double T1) { return PowerLawCp{}.enthalpy_rise(T0, T1); }

double bauxite_temperature_at_enthalpy(double h) { return PowerLawCp{}.temperature_at_enthalpy(h); }

}  // namespace centrec::thermal
