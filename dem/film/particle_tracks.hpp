#pragma once
// Particle tracks of a fed drum and the residence-time distribution they give
// (docs/particle_paths.md): at every sampled snapshot, each free particle's id, axial
// position and distance from the axis. Ids are never reused, so a particle first seen after
// the first snapshot was fed during the tracks, and one last seen before the last snapshot
// left through the outlet.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/film/particle_arrays.hpp"

namespace centrec::film {

struct TrackSnapshot {
  double time = 0.0;             // s
  std::vector<std::int64_t> id;  // particle ids
  std::vector<double> z;         // m, along the drum axis from the back plate
  std::vector<double> r;         // m, distance from the axis
};

// The track record of one snapshot.
TrackSnapshot track_snapshot(const ParticleColumns& s);

// One particle's path from the snapshot before it was first seen to the one after it was
// last seen: points[k] at snapshot first + k.
struct ParticlePath {
  std::int64_t id = 0;
  std::size_t first = 0;  // snapshot index of the first point
  std::vector<double> z, r;
  double entry = 0.0, exit = 0.0;  // s, midway between the snapshots around its feed and its exit
  double residence() const { return exit - entry; }
};

// The paths of the particles fed and gone within the tracks (first seen after snapshot 0,
// last seen before the last). Throws std::invalid_argument on snapshots out of time order or
// a particle that reappears after a snapshot without it.
std::vector<ParticlePath> complete_paths(const std::vector<TrackSnapshot>& tracks);

// The residence-time distribution from the complete paths of tracks W long: a residence tau
// is seen only for feeds in the first W - tau of the window, so each path carries the weight
// W / (W - tau) (the distribution of every feed, not of the short-lived ones; tau near W
// is not measured). resolution = the snapshot spacing (entry and exit are each known within
// half of it).
struct ResidenceTimes {
  std::vector<double> tau, weight;  // s, 1: one per complete path, in its order (weight 0: tau >= W - resolution)
  double window = 0.0;              // s, W
  double resolution = 0.0;          // s
  std::size_t fed = 0, left = 0;    // particles first seen after snapshot 0, last seen before the last
  double mean() const;              // s, weighted
  double quantile(double p) const;  // s, weighted (p in [0, 1])
  // Weighted share of residences below `t`.
  double share_below(double t) const;
  // The weights' sum over the particles fed in the window: 1 when every feed's residence is
  // below W (what is missing is the tail W and longer).
  double coverage() const;
};
// The p-quantile of `values` weighted by `weights` (p in [0, 1]); NaN when empty.
double weighted_quantile(const std::vector<double>& values, const std::vector<double>& weights, double p);

ResidenceTimes residence_times(const std::vector<TrackSnapshot>& tracks, const std::vector<ParticlePath>& paths);

}  // namespace centrec::film
