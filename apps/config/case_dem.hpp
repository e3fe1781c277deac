#pragma once
// The `dem:` section of a case file -> the CentRec scene config and the run settings.
#include <string>

#include "config/strict_yaml.hpp"
#include "dem/scene/scene_config.hpp"
#include "dem/scene/scene_sampler.hpp"

namespace centrec::config {

struct DemRunSpec {
  double duration = 1.0;          // s of simulated time before sampling starts
  double max_extension = -1.0;    // s: spin-up extended past `duration` until steady, by at most this (-1: duration)
  double extension_cap() const { return max_extension < 0.0 ? duration : max_extension; }
  double progress_interval = 0.0; // s of wall time between progress lines (0 = auto)
  double flow_window_turns = 5.0; // turns over which inlet/outlet mass flows are averaged
  double steady_tolerance = 0.05; // steady flow (dem/scene/mass_flow_window.hpp) within this over the window
  double checkpoint_interval = 300.0;  // s of wall time between DIR/checkpoint.h5 writes (0 = off)
};

struct DemSamplingSpec {
  double turns = 0.0;  // drum turns sampled after run.duration (0 = no film fields)
  dem::scene::SamplingSpec sampler;
};

struct DemCase {
  dem::scene::SceneConfig scene;
  DemRunSpec run;
  DemSamplingSpec sampling;
  // dem.initial_film.from_run as written (relative to the case file): a settled start from
  // that `centrec dem` run's last state (runs/settled_start.hpp); empty = none.
  std::string initial_film_from_run;
};

// Reads `dem` (a child mapping of the case root); strict: unknown keys are errors.
DemCase read_dem_case(MapReader dem);
// The folder of a settled start's source run (dem.initial_film.from_run), relative to the
// case file's folder unless absolute.
std::string settled_start_dir(const std::string& case_path, const DemCase& dc);

}  // namespace centrec::config
