#include "bauxite.hpp"

#include <algorithm>
#include <cmath>

namespace centrec::thermal {

namespace {
constexpr double kCpCoeff = 148.2;
constexpr double kCpExp = 0.3093;
}  // namespace

double bauxite_cp(double T) { return kCpCoeff * std::pow(T, kCpExp); }

double bauxite_enthalpy_rise(double T0, double T1) {
  const double p = kCpExp + 1.0;
  return kCpCoeff / p * (std::pow(T1, p) - std::pow(T0, p));
}

double bauxite_temperature_at_enthalpy(double h) {
  const double p = kCpExp + 1.0;
  return std::pow(std::max(h, 0.0) * p / kCpCoeff, 1.0 / p);
}

}  // namespace centrec::thermal
