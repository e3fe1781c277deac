#pragma once
// Scale-down laws of the paper, eqs. (1)-(3): keep omega^2 r, mdot/r and L/r.

namespace centrec::coupling {

struct ReceiverOperatingPoint {
  double diameter = 0.0;        // m
  double length = 0.0;          // m
  double omega = 0.0;           // rad/s
  double mass_flow = 0.0;       // kg/s
};

// The receiver of diameter `target_diameter` that carries the same film as `actual`.
ReceiverOperatingPoint scale_to_diameter(const ReceiverOperatingPoint& actual, double target_diameter);

double rpm_to_rad_per_s(double rpm);
double rad_per_s_to_rpm(double omega);

}  // namespace centrec::coupling
