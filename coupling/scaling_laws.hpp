#pragma once
// Scale-down laws of the paper, eqs. (1)-(3): keep omega^2 r, mdot/r and L/r.
#include <string>

namespace centrec::coupling {

struct ReceiverOperatingPoint {
  double diameter = 0.0;        // m
  double length = 0.0;          // m
  double omega = 0.0;           // rad/s
  double mass_flow = 0.0;       // kg/s
};

// The receiver of diameter `target_diameter` that carries the same film as `actual`.
ReceiverOperatingPoint scale_to_diameter(const ReceiverOperatingPoint& actual, double target_diameter);

// Derived quantities of an operating point (paper Table 2 lists the first; the second
// is what eq (1) keeps).
double inlet_speed(const ReceiverOperatingPoint& op);  // omega R, m/s: the wall speed particles enter with
double centrifugal_ratio(const ReceiverOperatingPoint& op, double gravity = 9.81);  // omega^2 R / g

// Particles in a film of thickness t (m) at solid fraction phi lining the wall over the
// length: phi pi (R^2 - (R - t)^2) L / (pi d^3 / 6).
double film_particle_count(const ReceiverOperatingPoint& op, double film_thickness, double solid_fraction,
                           double particle_diameter);

// Holdup carried to another size: the film (thickness in d) is the same, the wall area
// scales with D L, i.e. with (r_sim / r_act)^2 by eq (3): N_sim = N_act (r_sim / r_act)^2.
double scale_particle_count(double n_actual, double actual_diameter, double target_diameter);

// The laws hold while D >> d: below this drum diameter over particle diameter the film is
// another regime (the whole circumference slides, the film thickens), measured in
// docs/validity_threshold.md. Coupled runs refuse a smaller DEM drum unless told otherwise.
constexpr double kMinimumDrumDiameterOverD = 80.0;
// "" when D/d >= the threshold, else the sentence that says why D/d is not valid.
std::string scale_down_validity(double drum_diameter, double particle_diameter);

double rpm_to_rad_per_s(double rpm);
double rad_per_s_to_rpm(double omega);

}  // namespace centrec::coupling
