#pragma once
// Runs the paper's film samplers (dem/film, docs/film_sampling.md) on a CentRec scene:
// snapshots several times per turn, a period per turn, then reduces everything to the
// averaged film fields with their standard deviations over turns.
#include <memory>
#include <vector>

#include "dem/film/dispersion.hpp"
#include "dem/film/film_sections.hpp"
#include "dem/film/ring_profile.hpp"
#include "dem/film/solid_fraction.hpp"
#include "dem/film/velocity_profile.hpp"
#include "dem/film/zone_boundaries.hpp"
#include "dem/scene/centrec_scene.hpp"

namespace centrec::dem::scene {

struct SamplingSpec {
  int snapshots_per_turn = 8;
  int axial_sections = 20;
  int tangential_bins = 36;
  double bin_width_d = 0.5;   // wall-distance bins, in d
  int bins = 16;
  double zone_threshold = 0.1;  // moving zone: surface axial velocity above this x max
  // Dispersion (docs/film_sampling.md "Wall-normal dispersion"): the fine series' position
  // samples this far apart inside every snapshot interval, rounded to whole feeder batches
  // (0 = one batch), and its lags of 1..dispersion_lags sample spacings; the coarse series
  // (the snapshots) adds lags of 1..snapshots_per_turn - 1 snapshot intervals.
  double dispersion_spacing = 0.0;  // s
  int dispersion_lags = 20;
};

// One snapshot of the free particles in the sampler's SoA layout (copied from the engine).
using SnapshotArrays = film::ParticleColumns;
SnapshotArrays take_snapshot(const Simulation& sim);

// The film as the sampler measured it over the sampled turns (docs/film_sampling.md): what
// dem.h5 /film holds and the coupling reads.
struct SampledFilm {
  std::size_t turns = 0, snapshots = 0;
  film::LengthStat mean_thickness;                    // whole film
  std::vector<double> section_z;                      // m, axial section centres
  std::vector<film::LengthStat> section_thickness;    // per axial section
  std::vector<double> bin_theta;                      // rad, tangential bin centres
  std::vector<double> surface_velocity;               // per tangential bin, m/s
  film::ZoneDetection zones;
  std::vector<film::ArcSection> arcs;
  std::vector<std::vector<film::ProfileBin>> velocity_profiles;  // [arc][bin] m/s
  std::vector<double> bin_centre_d;                              // wall distance, d
  std::vector<std::vector<film::ProfileBin>> solid_fraction;     // [0 stationary, 1 moving][bin]
  std::vector<film::DispersionBin> dispersion;                   // per wall-distance bin
  std::vector<double> dispersion_lags;                           // s, the MSD's lags
  double dispersion_z_min = 0.0, dispersion_z_max = 0.0;         // m, window of the starting positions
  double dispersion_crossing_fraction = 0.0;                     // fit lags <= this x bin-crossing time
  // Full-circumference profiles per axial section (dem/film/ring_profile.hpp): the film
  // the coupling hands to the thermal model. [section][bin], on the bin_centre_d axis.
  std::vector<double> ring_z;                                    // m, section centres
  std::vector<std::vector<film::ProfileBin>> ring_solid_fraction;  // 1
  std::vector<std::vector<film::ProfileBin>> ring_volume_flux;     // m/s: phi * u
};

// Engine-neutral: the frame comes from the SceneConfig alone, so snapshots read from
// another engine's dumps (LIGGGHTS) feed the same samplers through add_snapshot/end_turn.
class SceneSampler {
 public:
  SceneSampler(const SceneConfig& config, const SamplingSpec& spec);
  SceneSampler(const CentrecScene& scene, const SamplingSpec& spec) : SceneSampler(scene.config(), spec) {}
  // Advances the native scene by `turns` drum turns, sampling as it goes.
  void sample_turns(CentrecScene& scene, double turns);
  // Advances the native scene by one snapshot interval (turn period / snapshots_per_turn)
  // in the batches one scene.advance(interval) makes, so the trajectory is bitwise the
  // same, and takes the dispersion's burst of position samples at batch ends on the way.
  // The caller then takes the snapshot (add_snapshot).
  void advance_interval(CentrecScene& scene);

  // One snapshot of the free particles, taken snapshots_per_turn times per turn (also the
  // dispersion's coarse series: lags of whole snapshot intervals within a turn).
  void add_snapshot(SnapshotArrays s);
  // Closes the current turn (one period of the velocity and solid-fraction samplers).
  void end_turn();
  SampledFilm fields() const;
  const film::DrumFrame& frame() const { return frame_; }
  const SamplingSpec& spec() const { return spec_; }
  // Checkpoints: every accumulator as one array; load() into a sampler built for the same
  // scene and spec continues exactly where save() left off (at a snapshot interval's end,
  // where no fine dispersion burst is open; the coarse series' snapshots of an unfinished
  // turn are saved with it).
  std::vector<double> save() const;
  void load(const std::vector<double>& state);

 private:
  SamplingSpec spec_;
  film::DrumFrame frame_;
  film::FilmSectionGrid grid_;
  film::FilmThicknessAccumulator thickness_;
  std::unique_ptr<film::VelocityProfileSampler> velocity_;
  std::unique_ptr<film::SolidFractionSampler> solid_;  // one zone per tangential bin
  std::unique_ptr<film::DispersionEstimator> dispersion_;
  std::unique_ptr<film::RingProfileSampler> ring_;
  std::size_t turns_ = 0, snapshots_ = 0;
};

}  // namespace centrec::dem::scene
