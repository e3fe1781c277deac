#pragma once
// The `receiver:` section of a coupled case: the actual (full-size)
// receiver's operating point. The coupled run simulates a scaled-down drum (the `dem:`
// section, or one derived from this section by eqs 1-3 when `dem_diameter_d` is given)
// and scales the film back up to this receiver.
#include <optional>

#include "config/case_dem.hpp"
#include "config/strict_yaml.hpp"
#include "coupling/scaling_laws.hpp"

namespace centrec::config {

// The `receiver:` section's keys as written; every command that takes a receiver reads it
// here. With `complete`, the operating point (diameter, length, speed_rpm, mass_flow) is
// required; without it (`centrec scale`, whose flags may give them) a key may be absent.
struct ReceiverSection {
  std::optional<double> diameter, length;  // m
  std::optional<double> speed_rpm;         // rev/min
  std::optional<double> mass_flow;         // kg/s
  double tilt = 0.0;                       // rad
  double dem_diameter_d = 0.0;             // > 0: derive the DEM drum at D = this x d
  std::optional<double> particle_diameter;  // m (absent: the DEM's particles)
};

// Reads every key of `receiver` and checks that no other is given.
ReceiverSection read_receiver_section(MapReader receiver, bool complete);

struct ReceiverCase {
  coupling::ReceiverOperatingPoint op;  // diameter, length, omega, mass_flow (SI)
  double tilt = 0.0;                    // rad
  double dem_diameter_d = 0.0;          // > 0: derive the DEM drum at D = this x d
  double particle_diameter = 0.0;       // m; > 0: must be the DEM's particle diameter
};

// Reads `receiver` (a child of the case root) and, when it derives the DEM drum, checks
// that `dem.drum` gives no diameter/length/speed of its own (a contradiction).
ReceiverCase read_receiver(MapReader receiver, MapReader dem);

// Applies the receiver to the DEM case. With dem_diameter_d: the drum (diameter, length,
// speed, tilt) and the mass flow (the feeder's, or a slice's target) by eqs 1-3. Otherwise the given DEM drum is used
// as it is, unless `follow_speed_and_flow` (a sweep changed the receiver's operating point):
// then it keeps its size and takes the receiver's omega^2 R and mdot / R (eqs 1-2).
// Throws std::invalid_argument when the tilts disagree.
void apply_receiver(const ReceiverCase& r, DemCase& dem, bool follow_speed_and_flow);

// The DEM drum's operating point (for scale-up records).
coupling::ReceiverOperatingPoint dem_operating_point(const DemCase& dem);

}  // namespace centrec::config
