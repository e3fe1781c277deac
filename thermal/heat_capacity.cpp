#include "heat_capacity.hpp"

namespace centrec::thermal {

// scale = 1 multiplies and divides exactly, so the unscaled correlation is bitwise unchanged.
double HeatCapacity::cp(double T) const { return scale * (cp_constant > 0.0 ? cp_constant : power_law.cp(T)); }

double HeatCapacity::enthalpy(double T) const {
  return scale * (cp_constant > 0.0 ? cp_constant * T : power_law.enthalpy_rise(0.0, T));
}

double HeatCapacity::temperature(double h) const {
  const double hs = h / scale;
  return cp_constant > 0.0 ? hs / cp_constant : power_law.temperature_at_enthalpy(hs);
}

}  // namespace centrec::thermal
