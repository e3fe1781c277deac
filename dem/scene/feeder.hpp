#pragma once
// The feeder (docs/centrec_scene.md, paper Fig. 1): particles enter from a region whose
// centre lies a radial offset inside the wall near the inlet, with the wall's tangential
// speed omega R and no axial velocity, at a mass flow rate; never overlapping.
#include <cstdint>
#include <random>
#include <string>

#include "dem/scene/scene_config.hpp"
#include "dem/scene/size_distribution.hpp"
#include "dem/simulation.hpp"

namespace centrec::dem::scene {

struct FeederStats {
  double inserted_mass = 0.0;        // kg
  std::int64_t inserted = 0;         // particles
  std::int64_t deferred = 0;         // insertions postponed because the region was full
  double requested_mass = 0.0;       // kg the target rate asked for so far
};

// Whether the feeder keeps up with its mass flow, judged once `stats` cover at least one drum
// turn: empty if it does; otherwise the reason, with the rate delivered and the keys that
// widen the region. Fed particles leave the region at the wall's speed, so its throughput is
// about its radial x axial cross-section times that speed: a region sized in d for a small
// drum (the defaults) cannot carry the paper's flows at D/d 80-100 (docs/centrec_scene.md).
// A region that is full defers insertions and keeps the backlog, so the shortfall is
// cumulative: below 90 % of the mass asked with deferred insertions, the drum is underfed.
std::string feeder_shortfall(const SceneConfig& config, const FeederStats& stats, double elapsed);

// Everything the feeder carries from one batch to the next (checkpoints).
struct FeederState {
  std::string size_rng, place_rng;  // generator states (std::mt19937_64 stream format)
  double backlog = 0.0;             // kg
  double next_diameter = 0.0;       // m
  FeederStats stats;
};

// Where the feeder may put the centre of a particle of radius `radius`: its sector shrunk
// by the radius on every side (along the arc at the sector's middle radius rc). The native
// feeder draws centres uniformly in it; the LIGGGHTS deck's insertion regions are this range
// for the largest particle.
struct FeederCentreRange {
  double rc = 0.0;            // m, middle radius of the sector
  double radial_width = 0.0;  // m, centres within rc -+ radial_width / 2 (>= 0)
  double arc_length = 0.0;    // m along rc, centres within angle -+ arc_length / (2 rc)
  double z0 = 0.0;            // m, centres in [z0, z0 + axial_width]
  double axial_width = 0.0;   // m (>= 0)
};
FeederCentreRange feeder_centre_range(const SceneConfig& config, double radius);

class Feeder {
 public:
  // Fed particles are made of `particle_material` (the scene's material for the case's
  // particles); their mass is booked with the case's particle density, the same one.
  Feeder(const SceneConfig& config, MaterialId particle_material, std::uint64_t seed);
  // Inserts the mass due over `elapsed` seconds (plus any backlog); returns the mass inserted.
  double feed(Simulation& sim, double elapsed);
  const FeederStats& stats() const { return stats_; }
  FeederState state() const;
  void restore(const FeederState& s);

 private:
  SceneConfig cfg_;
  MaterialId material_;
  SizeSampler sizes_;
  std::mt19937_64 rng_;
  double backlog_ = 0.0;        // kg due but not yet inserted
  double next_diameter_ = 0.0;  // the next particle's size, drawn once so deferral keeps it
  FeederStats stats_;
};

}  // namespace centrec::dem::scene
