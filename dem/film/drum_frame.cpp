#include "drum_frame.hpp"

#include <stdexcept>

namespace centrec::film {

double wrap_angle(double a) {
  const double two_pi = 2.0 * M_PI;
  a = std::fmod(a, two_pi);
  if (a < 0.0) a += two_pi;
  if (a >= two_pi) a = 0.0;  // fmod of a tiny negative can round up to 2 pi
  return a;
}

DrumFrame DrumFrame::from_gravity(double radius, double length, double gx, double gy, double omega_z,
                                  double theta_of_top) {
  if (!(radius > 0.0) || !(length > 0.0))
    throw std::invalid_argument("DrumFrame: radius and length must be positive");
  if (std::hypot(gx, gy) == 0.0)
    throw std::invalid_argument("DrumFrame: gravity has no component across the drum axis; the top is undefined");
  if (omega_z == 0.0) throw std::invalid_argument("DrumFrame: omega_z = 0, the rotation direction is undefined");
  DrumFrame f;
  f.radius = radius;
  f.length = length;
  f.top_polar_angle = std::atan2(-gy, -gx);
  f.rotation_sign = omega_z > 0.0 ? 1 : -1;
  f.theta_of_top = theta_of_top;
  return f;
}

double DrumFrame::theta(double x, double y) const {
  // Against the rotation: for a drum turning right-handed about +z, theta runs left-handed.
  const double phi = std::atan2(y, x);
  return wrap_angle(theta_of_top - rotation_sign * (phi - top_polar_angle));
}

}  // namespace centrec::film
