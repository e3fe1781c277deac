#pragma once
// The DEM's averaged film fields as the coupling reads them (what `centrec dem` writes to
// dem.h5 /film, docs/film_sampling.md), plus the DEM drum's operating point and its
// measured flow. Plain data, SI units; wall distances of the profile bins in particle
// diameters d, as the samplers give them. Made from a DEM run by coupling/dem_film_from_run;
// a cached run's dem.h5 is read back at the program's edge (apps/io/dem_film_h5).
#include <string>
#include <vector>

namespace centrec::coupling {

struct DemFilmAverages {
  // The simulated drum and its measured state.
  double drum_radius = 0.0;        // m
  double length = 0.0;             // m (the drum's, also for a slice)
  double omega = 0.0;              // rad/s
  double particle_diameter = 0.0;  // m
  double particle_density = 0.0;   // kg/m3
  bool slice = false;              // a periodic slice: one axial section, z-independent
  double feed_end = 0.0;           // m from the back plate: the downstream end of the feeder region (0 = no feeder)
  double sampled_turns = 0.0;
  // Flow over the last flow window (dem/scene/mass_flow_window.hpp): measured = the outlet
  // (drum) or the axial flow (slice); target = the feed (drum) or the controller's target.
  double mdot = 0.0;         // kg/s, measured
  double mdot_target = 0.0;  // kg/s
  bool steady = false;
  std::string steady_text;   // one line, as the DEM run printed it

  // Film thickness per axial section (eqs 4-7, ring average), m: the paper's thickness,
  // reported beside the film the thermal model receives.
  std::vector<double> section_z, thickness, thickness_std;
  // Share of the circumference in the moving zone (surface velocity above the zone
  // threshold): a diagnostic of the regime (docs/validity_threshold.md).
  double moving_fraction = 0.0;
  // Wall-distance bins (centres, in d; equal widths) of the profiles below.
  std::vector<double> wall_distance_d;
  // Full-circumference profiles per axial section ring_z [section][bin]: solid fraction of
  // the free particles and axial volume flux density phi * u (m/s), with their spread over
  // turns (dem/film/ring_profile.hpp).
  std::vector<double> ring_z;
  std::vector<std::vector<double>> ring_phi, ring_phi_std, ring_flux, ring_flux_std;
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
