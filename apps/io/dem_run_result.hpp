#pragma once
// What a DEM run hands to its outputs (dem_run_report, dem_output_h5), whichever
// engine produced it: counts, timings, the mass-flow log, the sampled film fields
// and the particle snapshots. Engine-neutral: no reference to the native scene.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_sampler.hpp"

namespace centrec::io {

// dem.h5 and dem.xmf keep every sampled snapshot while they hold at most this many particle
// records in all (about 75 MB per million); a longer sampling keeps every k-th snapshot,
// k = snapshot_stride(...), so a full-size drum's hundreds of turns fit in memory and on disk.
constexpr double kSnapshotRecordBudget = 5e6;
inline int snapshot_stride(double snapshots, double particles) {
  return std::max(1, static_cast<int>(std::ceil(snapshots * particles / kSnapshotRecordBudget)));
}

struct NamedSnapshot {
  std::string name;  // group name, e.g. "t0.500000"
  dem::scene::SnapshotArrays data;    // the free particles (what the film samplers see)
  dem::scene::SnapshotArrays glued;   // the glued rough-wall layer at the same time (may be empty)
};

struct DemRunResult {
  std::string engine = "centrec";  // "centrec" (native) or "liggghts"
  std::string engine_version;
  int threads = 1;  // threads per process
  int ranks = 1;    // MPI processes
  double simulated_time = 0.0;  // s
  double dt = 0.0;              // s
  std::int64_t steps = 0;
  std::int64_t free_particles = 0, glued_particles = 0;
  double holdup_kg = 0.0;
  std::vector<dem::scene::MassFlowSample> mass_flow;  // cumulative, one entry per batch/dump
  std::int64_t feeder_deferred = 0;   // feeder insertions postponed for lack of room (< 0: unknown, null)
  double contacts_per_particle = -1.0;  // < 0: the engine did not report it (null in JSON)
  double particle_steps = 0.0;
  double moving_particle_steps = 0.0;  // of free particles only (the glued wall layer left out); < 0: unknown
  double wall_time = 0.0;  // s
  // Wall time per phase of the native engine's run (name, s), in print order; empty for
  // another engine. Their sum is the run's wall time ("other": what no phase timer holds).
  std::vector<std::pair<std::string, double>> phase_seconds;
  std::int64_t neighbour_rebuilds = -1, list_edits = -1;  // this process's (< 0: unknown)
  double pair_pass_idle = 0.0, parked_pass_idle = 0.0;   // s of force_pass threads waited (EngineTimes)
  std::vector<dem::scene::ControllerWindow> controller;  // slice holdup controller windows
  dem::scene::SampledFilm fields;
  std::vector<NamedSnapshot> snapshots;
  int snapshot_stride = 1;  // every k-th sampled snapshot kept in `snapshots`
};

}  // namespace centrec::io
