#pragma once
// Scale-up of a film field from the simulated (scaled-down) drum to the actual receiver
// (docs/scaling.md): the particles are the same, so u(eta / d), t / d,
// phi(eta / d) and D(eta / d) carry over unchanged and axial positions stretch by
// L_act / L_sim. The operating point (diameter, length, omega, mdot) becomes the
// receiver's. The film's mass flux is not touched: conserve_mass_flow then imposes the
// receiver's mdot, and its factor measures how far eq (2) holds at this D/d.
#include <string>

#include "coupling/scaling_laws.hpp"
#include "thermal/film_field.hpp"

namespace centrec::coupling {

struct ScaleUpRecord {
  double length_ratio = 1.0;   // L_act / L_sim (the z stretch)
  double radius_ratio = 1.0;   // r_act / r_sim
  double omega_ratio = 1.0;    // omega_act / omega_sim (eq 1: sqrt(r_sim / r_act))
  double mdot_ratio = 1.0;     // mdot_act / mdot_sim of the configured feed (eq 2: r_act / r_sim)
  // Deviations of the simulated drum (its configured speed, feed, length) from eqs 1-3
  // applied to the receiver: 0 when derived, round-off when scaled by hand.
  double eq1_error = 0.0, eq2_error = 0.0, eq3_error = 0.0;
  std::string description;
};

// `sim` has the true simulated drum's diameter and length in its metadata (its mdot is the
// DEM's measured flow); `simulated` is the DEM drum's configured operating point.
thermal::FilmField scale_up_film(const thermal::FilmField& sim, const ReceiverOperatingPoint& simulated,
                                 const ReceiverOperatingPoint& actual, ScaleUpRecord* record = nullptr);

}  // namespace centrec::coupling
