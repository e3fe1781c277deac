#pragma once
// Axial velocity vs wall distance in arc-like film sections (paper Figs 5 and 6).
// Default sections: theta = 45, 90, 135 deg (convention in drum_frame.hpp) x
// z/L = 0.3, 0.5, 0.7. A particle belongs to a section if its centre lies within
// +-arc_half_width of theta and +-axial_half_length of z; it is binned by its centre's
// wall distance w = R - r in particle diameters (the paper's axis r_p: centres below
// 1 d are the wall layer, which the paper finds at rest).
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/period_profile.hpp"
#include "dem/film/wall_distance_bins.hpp"

namespace centrec::film {

struct ArcSection {
  double theta = 0.0;          // rad
  double z_over_length = 0.0;  // z / L
};

// The paper's nine sections, ordered z-major: (45,0.3) (90,0.3) (135,0.3) (45,0.5) ...
std::vector<ArcSection> paper_arc_sections();

struct VelocityProfileConfig {
  std::vector<ArcSection> sections = paper_arc_sections();
  double arc_half_width = 7.5 * M_PI / 180.0;  // rad
  double axial_half_length = 0.05;             // as a fraction of L
  WallDistanceBins bins;                       // set bins.particle_diameter
};

class VelocityProfileSampler {
 public:
  VelocityProfileSampler(const DrumFrame& frame, VelocityProfileConfig config);
  // Adds every particle of the snapshot (needs x, y, z, vz) to the current period.
  void add_snapshot(const ParticleArrays& p);
  // Closes the period (call once per turn): the period's bin means become one sample.
  void end_period();
  std::size_t periods() const { return periods_; }
  const VelocityProfileConfig& config() const { return config_; }
  // Profile of one section: bin k at wall distance config().bins.centre_d(k).
  std::vector<ProfileBin> profile(int section) const;
  void save(PackedState& out) const;  // checkpoints (dem/film/packed_state.hpp)
  void load(StateReader& in);         // into a sampler built with the same config

 private:
  DrumFrame frame_;
  VelocityProfileConfig config_;
  std::vector<PeriodProfile> profiles_;
  std::size_t periods_ = 0;
};

}  // namespace centrec::film
