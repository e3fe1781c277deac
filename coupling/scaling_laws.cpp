#include "scaling_laws.hpp"

#include <cmath>
#include <cstdio>
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

double inlet_speed(const ReceiverOperatingPoint& op) { return op.omega * 0.5 * op.diameter; }

double centrifugal_ratio(const ReceiverOperatingPoint& op, double gravity) {
  return op.omega * op.omega * 0.5 * op.diameter / gravity;
}

double film_particle_count(const ReceiverOperatingPoint& op, double t, double phi, double d) {
  const double R = 0.5 * op.diameter;
  if (!(t > 0.0 && t < R) || !(phi > 0.0 && phi < 1.0) || !(d > 0.0))
    throw std::invalid_argument("film_particle_count: need 0 < t < R, 0 < phi < 1, d > 0");
  return phi * M_PI * (R * R - (R - t) * (R - t)) * op.length / (M_PI * d * d * d / 6.0);
}

double scale_particle_count(double n_actual, double actual_diameter, double target_diameter) {
  if (!(actual_diameter > 0.0) || !(target_diameter > 0.0))
    throw std::invalid_argument("scale_particle_count: diameters must be positive");
  const double ratio = target_diameter / actual_diameter;
  return n_actual * ratio * ratio;
}

double rpm_to_rad_per_s(double rpm) { return rpm * 2.0 * M_PI / 60.0; }
double rad_per_s_to_rpm(double omega) { return omega * 60.0 / (2.0 * M_PI); }

std::string scale_down_validity(double drum_diameter, double particle_diameter) {
  const double dd = drum_diameter / particle_diameter;
  if (dd >= kMinimumDrumDiameterOverD) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "the DEM drum is D/d = %.4g, below the scale-down laws' validity threshold D/d = %.0f measured in "
                "docs/validity_threshold.md (smaller drums are another regime: the film slides all round and thickens)",
                dd, kMinimumDrumDiameterOverD);
  return text;
}

}  // namespace centrec::coupling
