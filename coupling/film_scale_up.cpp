#include "film_scale_up.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace centrec::coupling {

thermal::FilmField scale_up_film(const thermal::FilmField& sim, const ReceiverOperatingPoint& simulated,
                                 const ReceiverOperatingPoint& actual, ScaleUpRecord* record) {
  if (!(sim.drum_diameter > 0.0 && sim.length > 0.0))
    throw std::invalid_argument("scale_up_film: the simulated film needs a positive diameter and length");
  if (!(simulated.omega > 0.0 && simulated.mass_flow > 0.0))
    throw std::invalid_argument("scale_up_film: the simulated drum needs a positive speed and mass flow");
  if (!(actual.diameter > 0.0 && actual.length > 0.0 && actual.omega > 0.0 && actual.mass_flow > 0.0))
    throw std::invalid_argument("scale_up_film: the receiver needs positive diameter, length, omega and mass flow");
  ScaleUpRecord r;
  r.length_ratio = actual.length / sim.length;
  r.radius_ratio = actual.diameter / sim.drum_diameter;
  r.omega_ratio = actual.omega / simulated.omega;
  r.mdot_ratio = actual.mass_flow / simulated.mass_flow;
  // Eqs (1)-(3): omega^2 r, mdot / r and L / r kept.
  r.eq1_error = r.omega_ratio * r.omega_ratio * r.radius_ratio - 1.0;
  r.eq2_error = r.mdot_ratio / r.radius_ratio - 1.0;
  r.eq3_error = r.length_ratio / r.radius_ratio - 1.0;
  char text[512];
  std::snprintf(text, sizeof text,
                "scaled up from the DEM drum D = %.6g m, L = %.6g m, omega = %.6g rad/s, fed %.6g kg/s (outlet "
                "%.6g kg/s) to D = %.6g m, L = %.6g m, omega = %.6g rad/s, mdot = %.6g kg/s (eqs 1-3; z x %.6g, "
                "u(eta/d), t/d, phi, D kept; eq 1/2/3 deviations of the DEM drum %.2e/%.2e/%.2e)",
                sim.drum_diameter, sim.length, simulated.omega, simulated.mass_flow, sim.mdot, actual.diameter, actual.length, actual.omega,
                actual.mass_flow, r.length_ratio, r.eq1_error, r.eq2_error, r.eq3_error);
  r.description = text;
  thermal::FilmField f = sim;
  for (double& z : f.z) z *= r.length_ratio;
  f.drum_diameter = actual.diameter;
  f.length = actual.length;
  f.omega = actual.omega;
  f.mdot = actual.mass_flow;
  f.scaling = r.description;
  if (record) *record = r;
  return f;
}

}  // namespace centrec::coupling
