#pragma once
// Solid fraction vs wall distance, separately per zone (paper section 4: porosity ~0.48
// in the stationary zone, ~0.52 in the moving zone).
//
// For each snapshot, each zone z and wall-distance bin k (annular shell R - w_hi < r <= R - w_lo):
//   phi[z][k] = sum over particles of V(sphere inside the shell) / V(shell part of zone z)
// The radial split of each sphere is exact geometry (sphere_shell_volume.hpp); in theta
// and z a sphere is assigned whole by its centre. That assignment is unbiased for a film
// statistically uniform along theta and z over a sphere's size (what leaks out of a
// region across its edge is matched by what leaks in), while the radial direction,
// where the wall layers the packing, is resolved exactly.
//
// Zones: each of the tangential bins (theta over [0, 2 pi), equal width) is given a zone
// index (0 = stationary, 1 = moving from zone_boundaries.hpp, or any labelling).
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/period_profile.hpp"
#include "dem/film/wall_distance_bins.hpp"

namespace centrec::film {

struct SolidFractionConfig {
  WallDistanceBins bins;            // set bins.particle_diameter
  std::vector<int> zone_of_bin{0};  // zone per tangential bin; its size sets the bin count
  double z_min = 0.0;               // m, axial window
  double z_max = -1.0;              // m; < 0 means the drum length
};

class SolidFractionSampler {
 public:
  SolidFractionSampler(const DrumFrame& frame, SolidFractionConfig config);
  // One snapshot (needs x, y, z, radius): its solid fraction per zone and bin is one
  // sample of the current period.
  void add_snapshot(const ParticleArrays& p);
  void end_period();
  int zones() const { return n_zones_; }
  const SolidFractionConfig& config() const { return config_; }
  // Profile of one zone: bin k at wall distance config().bins.centre_d(k).
  std::vector<ProfileBin> profile(int zone) const;
  void save(PackedState& out) const;  // checkpoints (dem/film/packed_state.hpp)
  void load(StateReader& in);         // into a sampler built with the same config

 private:
  DrumFrame frame_;
  SolidFractionConfig config_;
  int n_zones_ = 0;
  std::vector<double> zone_angle_;          // rad of theta covered by each zone
  std::vector<PeriodProfile> profiles_;
};

}  // namespace centrec::film
