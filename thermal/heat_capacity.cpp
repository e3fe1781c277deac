#include "heat_capacity.hpp"

#include <cmath>

#include "bauxite.hpp"

namespace centrec::thermal {

double HeatCapacity::cp(double T) const { return cp_constant > 0.0 ? cp_constant : bauxite_cp(T); }

double HeatCapacity::enthalpy(double T) const {
  return cp_constant > 0.0 ? cp_constant * T : bauxite_enthalpy_rise(0.0, T);
}

double HeatCapacity::temperature(double h) const {
  return cp_constant > 0.0 ? h / cp_constant : bauxite_temperature_at_enthalpy(h);
}

}  // namespace centrec::thermal
