#pragma once
// The DEM's averaged film fields as the coupling reads them (what `centrec dem` writes to
// dem.h5 /film, docs/film_sampling.md), plus the DEM drum's operating point. Plain data, SI
// units; wall distances of the profile bins in particle diameters d, as the samplers give
// them. Made from a DEM run by coupling/dem_film_from_run; a cached run's dem.h5 is read
// back at the program's edge (apps/io/dem_film_h5).
#include <vector>

namespace centrec::coupling {

struct DemFilmAverages {
  // The simulated drum and its measured state.
  double drum_radius = 0.0;        // m
  double length = 0.0;             // m
  double omega = 0.0;              // rad/s
  double particle_diameter = 0.0;  // m
  double particle_density = 0.0;   // kg/m3
  double mdot = 0.0;               // kg/s, outlet mass flow over the last flow window
  double sampled_turns = 0.0;

  // Film thickness per axial section (eqs 4-7, ring average), m.
  std::vector<double> section_z, thickness, thickness_std;
  // Tangential bins: centre angle (rad), surface axial velocity (m/s), 1 = moving zone.
  std::vector<double> bin_theta, surface_velocity;
  std::vector<int> moving_zone_of_bin;
  // Wall-distance bins (centres, in d; equal widths) of the profiles below.
  std::vector<double> wall_distance_d;
  // Axial velocity in the arc sections [arc][bin], m/s; turns[arc][bin] = 0 marks an empty bin.
  std::vector<double> arc_theta, arc_z_over_length;
  std::vector<std::vector<double>> u_mean, u_std, u_turns;
  // Solid fraction per zone [bin]: stationary and moving.
  std::vector<double> phi_stationary, phi_stationary_std, phi_moving, phi_moving_std;
  // Solid fraction of the glued wall monolayer per bin (zeros without one): not sampled by
  // the DEM (free particles only), added by the mapping (coupling/glued_layer.hpp).
  std::vector<double> phi_glued;
  // Wall-normal dispersion per bin, m2/s.
  std::vector<double> dispersion, dispersion_std;

  double bin_width_d() const {
    return wall_distance_d.size() > 1 ? wall_distance_d[1] - wall_distance_d[0] : 2.0 * wall_distance_d.at(0);
  }
  // Throws std::invalid_argument naming the first missing or inconsistent item.
  void check() const;
};

}  // namespace centrec::coupling
