#pragma once
// Wall-normal self-diffusion (dispersion) coefficient vs wall distance: the mixing part
// of the film's effective conductivity (docs/film_sampling.md and docs/thermal_model.md).
//
// Estimator. Take pairs of snapshots a lag tau apart; follow each particle by id; its
// radial displacement dr = r(t + tau) - r(t) goes to the bin of its STARTING wall
// distance. Per bin:
//     D = ( <dr^2> - <dr>^2 ) / (2 tau)
// i.e. the variance of the displacement, so a mean radial drift u (settling, the
// film thinning along z) contributes its u^2 tau^2 to <dr^2> but not to D. Pairs are
// pooled (all displacements of all pairs in one mean per bin); the standard deviation
// of the per-pair estimates is reported as the spread. tau must be long against the
// collision time (diffusive regime) and short against the time to cross a bin or the
// film, or the wall and the free surface bound the displacement and D comes out low:
// check D is flat in tau. Particles absent from either snapshot (inserted or removed
// in between) are skipped.
#include <cstddef>
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/running_stats.hpp"
#include "dem/film/wall_distance_bins.hpp"

namespace centrec::film {

struct DispersionBin {
  double wall_distance_d = 0.0;  // bin centre, in d
  double coefficient = 0.0;      // D, m^2/s (NaN with fewer than 2 samples)
  double coefficient_std = 0.0;  // std of the per-pair estimates, m^2/s
  double drift = 0.0;            // <dr>/tau, m/s (> 0 away from the wall)
  std::size_t samples = 0;       // displacements
  std::size_t pairs = 0;         // snapshot pairs that contributed
};

class DispersionEstimator {
 public:
  DispersionEstimator(const DrumFrame& frame, WallDistanceBins bins);
  // Needs x, y, id in both; tau = end.time - start.time must be > 0 and the same for
  // every pair (within 1e-9 relative).
  void add_pair(const ParticleArrays& start, const ParticleArrays& end);
  double lag() const { return tau_; }
  std::vector<DispersionBin> result() const;
  void save(PackedState& out) const;  // checkpoints (dem/film/packed_state.hpp)
  void load(StateReader& in);         // into a sampler built with the same config

 private:
  DrumFrame frame_;
  WallDistanceBins bins_;
  double tau_ = 0.0;
  std::vector<double> sum_, sum2_;
  std::vector<std::size_t> n_;
  std::vector<RunningStats> per_pair_;
};

}  // namespace centrec::film
