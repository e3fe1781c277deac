#pragma once
// Full-circumference film profiles per axial section: what the thermal model's film is
// made of (docs/film_sampling.md "Ring profiles", docs/coupling.md).
//
// For each axial section a and wall-distance bin k (annular shell R - w_hi < r <= R - w_lo
// over the section's length), per snapshot:
//   phi[a][k]  = sum over particles of V(sphere inside the shell) / V(shell)
//   flux[a][k] = sum over particles of V(sphere inside the shell) * vz / V(shell)   (m/s)
// i.e. the solid fraction and the axial volume flux density phi * u, tangentially averaged
// over the whole circumference (stationary and moving zones together). The
// volume-weighted (= mass-weighted) axial velocity of the bin is flux / phi, and
//   rho_s * sum_k flux[a][k] * V(shell k) / L_a = rho_s * sum_i V_i vz_i / L_a
// is the section's axial mass flow carried by the particles within the bins: the profiles
// carry exactly the flow of the particles they cover, with no rescaling. The radial split
// of a sphere between shells is exact geometry (sphere_shell_volume.hpp); in z a sphere
// belongs whole to the section holding its centre (unbiased for a film uniform over a
// sphere's size, as solid_fraction.hpp).
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/period_profile.hpp"
#include "dem/film/wall_distance_bins.hpp"

namespace centrec::film {

struct RingProfileConfig {
  WallDistanceBins bins;  // set bins.particle_diameter
  int sections = 1;       // equal axial sections over [z_min, z_max)
  double z_min = 0.0;     // m
  double z_max = -1.0;    // m; < 0 means the drum length
};

class RingProfileSampler {
 public:
  RingProfileSampler(const DrumFrame& frame, RingProfileConfig config);
  // One snapshot (needs x, y, z, vz, radius).
  void add_snapshot(const ParticleArrays& p);
  void end_period();
  const RingProfileConfig& config() const { return config_; }
  double section_centre(int a) const;
  // Solid fraction and axial volume flux density (m/s) of section a, bin k at wall
  // distance config().bins.centre_d(k): mean and spread over periods.
  std::vector<ProfileBin> solid_fraction(int a) const { return phi_.at(a).all(); }
  std::vector<ProfileBin> volume_flux(int a) const { return flux_.at(a).all(); }
  void save(PackedState& out) const;  // checkpoints (dem/film/packed_state.hpp)
  void load(StateReader& in);         // into a sampler built with the same config

 private:
  DrumFrame frame_;
  RingProfileConfig config_;
  std::vector<PeriodProfile> phi_, flux_;  // per section
};

}  // namespace centrec::film
