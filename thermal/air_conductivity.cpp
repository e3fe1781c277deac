#include "air_conductivity.hpp"

#include <algorithm>

namespace centrec::thermal {

double air_conductivity(double T) {
  // Polynomial fit of air conductivity at 1 bar (100-1600 K); outside, hold the end
  // value so a Newton iterate that strays does not see a negative conductivity.
  const double x = std::clamp(T, 100.0, 1600.0);
  return ((1.5207e-11 * x - 4.8574e-8) * x + 1.0184e-4) * x - 3.9333e-4;
}

}  // namespace centrec::thermal
