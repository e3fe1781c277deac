#pragma once
// DIR/checkpoint.h5 of `centrec dem` (docs/outputs.md): the resolved case, the run's
// phase and the scene's full state (dem/scene/centrec_scene.hpp SceneState), written
// atomically through apps/io/h5_file (tmp + rename). Every dataset and attribute enters a
// checksum stored in the file, so a damaged checkpoint is refused instead of resumed.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dem/film/particle_arrays.hpp"
#include "dem/scene/centrec_scene.hpp"

namespace centrec::io {

// Named arrays of doubles (the sampler's accumulators), stored under /sampler.
using StateArrays = std::map<std::string, std::vector<double>>;

struct RunCheckpoint {
  std::string code_version;
  std::string case_path;      // as given to the first run (informative)
  std::string resolved_yaml;  // the case the run uses; --resume reads it from here
  std::string phase;          // "spin-up", "sampling" or "done"
  int sampled_turns = 0;      // turns sampled so far (phase "sampling"/"done")
  int turn_snapshots = 0;     // snapshots taken into the next, unfinished turn (phase "sampling")
  double particle_steps = 0.0;
  double wall_time = 0.0;     // s of wall time spent so far
  dem::scene::SceneState scene;
  StateArrays sampler;                               // phase "sampling"/"done"
  std::optional<film::ParticleColumns> start_snapshot;  // the film as sampling started
};

// Writes dir/checkpoint.h5 (via dir/checkpoint.h5.tmp and a rename).
void write_checkpoint(const std::string& dir, const RunCheckpoint& c);
// Reads dir/checkpoint.h5; throws std::runtime_error naming the file and the problem
// (missing, unreadable, wrong format, checksum mismatch).
RunCheckpoint read_checkpoint(const std::string& dir);
std::string checkpoint_path(const std::string& dir);

}  // namespace centrec::io
