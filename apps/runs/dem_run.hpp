#pragma once
// The native DEM run of a case, in named phases:
//   1. set-up    the scene built (or restored from a checkpoint), its time step stated;
//   2. spin-up   to run.duration, then on until the flow is steady over the flow window or
//                run.max_extension more has passed (dem/scene/mass_flow_window.hpp);
//   3. sampling  sampling.turns turns of snapshots for the film fields;
//   4. done      the engine-neutral io::DemRunResult.
// Between chunks of simulated time the run passes fixed points: the neighbour lists are
// rebuilt there, and only there a checkpoint is written or a Ctrl-C obeyed, so whether and
// when a checkpoint is written (wall clock) never changes the result and a resumed run
// continues bitwise (docs/reliability.md). A checkpoint inside a sampled turn keeps the
// samplers' partial turn.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "config/case_file.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_sampler.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/dem_run_result.hpp"
#include "io/particle_tracks_h5.hpp"
#include "runs/interrupt.hpp"
#include "runs/progress_meter.hpp"

namespace centrec::runs {

class DemRun {
 public:
  enum class Phase { spin_up, sampling, done };
  // As a checkpoint records the phase: "spin-up", "sampling", "done".
  static const char* name(Phase p);
  // Throws std::runtime_error for a name that is not a phase.
  static Phase phase_named(const std::string& name);

  // Phase 1: builds the scene of `dc` (from `ck` when given); out_dir holds the checkpoints.
  DemRun(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
         const std::optional<io::RunCheckpoint>& ck);
  // Phases 2-4 (a resumed run from the phase its checkpoint was in). Throws RunInterrupted
  // after writing a checkpoint when a signal came, config::ConfigError for an underfed drum.
  io::DemRunResult run();

 private:
  void spin_up();
  void start_sampling();
  void sample_turn();
  io::DemRunResult done();

  // Advances the run by `body` (a call that advances the scene), counting particle-steps
  // and reporting progress.
  template <class Body>
  void advance(Body&& body);
  // A fixed point of `phase`: lists rebuilt, a checkpoint if one is due, a stop if a signal came.
  void fixed_point(Phase phase);
  void checkpoint(Phase phase, bool force);
  // The snapshot `s` kept for dem.h5 and dem.xmf, with the glued layer as it is now.
  void keep(const dem::scene::SnapshotArrays& s, bool with_glued);
  // The tracks not yet on disk written as one part (io/particle_tracks_h5.hpp).
  void flush_tracks();
  // The flow over the last turn, for the progress lines.
  std::string flows() const;
  // The engine's and the scene's phase timers together (what the samplers' time excludes).
  double engine_seconds() const;

  const config::CaseFile& cf_;
  const config::DemCase& dc_;
  const std::string out_dir_;
  const io::RunCheckpoint* ck_;  // the checkpoint resumed from, or null
  dem::scene::CentrecScene scene_;
  dem::Simulation& sim_;
  // The timers and counters at the end of the set-up (its own list build and forces are not the run's).
  const dem::EngineTimes engine_at_start_;
  const dem::scene::SceneTimes scene_at_start_;
  const std::size_t rebuilds_at_start_, edits_at_start_;
  const double period_, chunk_;
  const double steps_before_, wall_before_;  // a resumed run's particle-steps and wall time before it
  ProgressMeter progress_;
  double particle_steps_ = 0.0, moving_steps_ = 0.0;       // this process's (all particles, free ones)
  double sampling_seconds_ = 0.0, checkpoint_seconds_ = 0.0;  // the samplers' own work, checkpoint writes
  dem::scene::SceneSampler sampler_;
  std::vector<io::NamedSnapshot> snapshots_;
  // A fed drum's particle tracks: every sampled snapshot's, written at each checkpoint and
  // at the end; track_first_ is the index of the first one not yet on disk.
  const bool tracks_;
  std::vector<io::TrackSnapshot> tracks_pending_;
  std::int64_t track_first_ = 0;
  int sampled_, in_turn_;  // whole sampled turns, snapshots taken into the unfinished one
  int turns_ = 0, per_turn_ = 0, stride_ = 1, taken_ = 0;  // set as the sampling starts
  std::chrono::steady_clock::time_point checkpoint_at_;
  const InterruptGuard interrupt_;
};

}  // namespace centrec::runs
