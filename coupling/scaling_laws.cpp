#include "scaling_laws.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::coupling {

ReceiverOperatingPoint scale_to_diameter(const ReceiverOperatingPoint& a, double target_diameter) {
  if (!(a.diameter > 0.0) || !(target_diameter > 0.0))
    throw std::invalid_argument("scale_to_diameter: diameters must be positive");
  const double ratio = target_diameter / a.diameter;  // r_sim / r_act
  ReceiverOperatingPoint s;
  s.diameter = target_diameter;
  s.omega = a.omega / std::sqrt(ratio);   // eq. (1): omega^2 r constant
  s.mass_flow = a.mass_flow * ratio;      // eq. (2): mdot / r constant
  s.length = a.length * ratio;            // eq. (3): L / r constant
  return s;
}

double rpm_to_rad_per_s(double rpm) { return rpm * 2.0 * M_PI / 60.0; }
double rad_per_s_to_rpm(double omega) { return omega * 60.0 / (2.0 * M_PI); }

}  // namespace centrec::coupling
