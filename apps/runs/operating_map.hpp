#pragma once
// A receiver's operating map (docs/operating.md): a `centrec sweep` over speed x mass flow,
// read back point by point. A point is usable when its run finished, its DEM film was at
// steady flow and the mapped film carried the DEM's flow within kMapClosureTolerance; any
// other point keeps the measured reason (the run's refusal from its run.log, or the
// figure that missed). The usable points form the stable window: a grid cell whose four
// corners are usable is inside it.
#include <string>
#include <vector>

#include "coupling/film_surrogate.hpp"

namespace centrec::runs {

constexpr double kMapClosureTolerance = 0.03;

struct MapPoint {
  double speed_rpm = 0.0, mass_flow = 0.0;  // rpm, kg/s
  std::string dir;
  bool usable = false;
  std::string state;                        // "steady, closure 100.1 %", or why not usable
  double T_out = 0.0, efficiency = 0.0;     // K, - (finished points; at the sweep's own flux)
};

// Distances from an operating point to the window's edges along the grid lines through it
// (0 when outside the window).
struct WindowMargin {
  double speed_below = 0.0, speed_above = 0.0;  // rpm
  double flow_below = 0.0, flow_above = 0.0;    // kg/s
};

// A map run on another receiver of the same scaled film, read as this receiver's. Eqs 1-2
// keep omega^2 R and mdot / R, so two receivers with the same DEM section, dem_diameter_d,
// tilt and L / D derive the same DEM drum at corresponding points: the other's speeds times
// sqrt(R_map / R), its mass flows times R / R_map, its films' length times L / L_map (the film
// in particle diameters and its velocities are the same; docs/operating.md).
struct MapScaling {
  double speed = 1.0, flow = 1.0, length = 1.0;
  bool identity() const { return speed == 1.0 && flow == 1.0 && length == 1.0; }
};

struct OperatingMap {
  std::string dir, case_path;
  MapScaling scaling;                 // applied to the points' speeds, flows and films as read
  std::vector<MapPoint> points;
  std::vector<double> speeds, flows;  // the grid's distinct values, ascending

  const MapPoint* at(std::size_t i_speed, std::size_t j_flow) const;  // nullptr: not on the map
  bool inside(double speed_rpm, double mass_flow) const;
  WindowMargin margin(double speed_rpm, double mass_flow) const;
  // The usable mass-flow span at a speed: the longest run of usable cells along the flow
  // axis through that speed ({0, 0} when none).
  std::pair<double, double> flow_span(double speed_rpm) const;
};

// Reads DIR/sweep.json of a `centrec sweep` whose axes are speed_rpm and mass_flow_kg_s, and
// perhaps each point's DEM start (dem.initial_film.*: a film near the point's own state); any
// other axis is refused: a film map is over the operating point only. Throws
// std::runtime_error naming the file and what is missing.
OperatingMap read_operating_map(const std::string& sweep_dir, const MapScaling& scaling = {});

// The scaling that reads the map in sweep_dir as one of the receiver whose resolved case is
// `case_resolved_yaml`: the identity for the same receiver, else the scaling between two
// receivers of the same scaled film. The map's own case is its first finished point's
// resolved configuration (summary.json), else the case file sweep.json names. Throws
// std::runtime_error naming every key that differs when the map is not of this scaled film:
// any DEM key but a point's start and spin-up, or the receiver's dem_diameter_d, tilt,
// particle diameter or L / D.
MapScaling map_scaling_for(const std::string& sweep_dir, const std::string& case_resolved_yaml);

// The usable points' films (DIR/<point>/film.h5), with drum_diameter set back to the
// receiver's (a run's film.h5 holds the planar diameter of its imposed flow), scaled by the
// map's scaling (length, z, omega and mass flow).
std::vector<coupling::SurrogateSample> surrogate_samples(const OperatingMap& m, double receiver_diameter);

}  // namespace centrec::runs
