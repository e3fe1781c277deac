#pragma once
// The DEM cache of `centrec run`: a DEM run's outputs are stored under CACHE/<key>/, the
// key a hash of every DEM input (the resolved `dem:` configuration less the thread count
// and intervals, the drum and feed the receiver derived, and the code version), so a run
// whose DEM inputs are unchanged (a thermal-only change) reuses them and reruns in seconds.
#include <functional>
#include <string>

#include "config/case_dem.hpp"

namespace centrec::runs {

// 16 hex digits of FNV-1a 64 over the DEM inputs of the case whose resolved configuration
// is `resolved_yaml` (its `dem:` section less the keys that change no result, e.g. the
// thread count) and the effective (derived) drum, flow and seed.
std::string dem_cache_key(const std::string& resolved_yaml, const config::DemCase& effective, const std::string& version);

struct CachedDem {
  std::string dir;  // CACHE/<key>, holding dem.h5 and summary.json
  bool hit = false;
  std::string resumed_from;  // the interrupted run's folder this one continued, if any
};

// Returns CACHE/<key> if it holds a complete run (its dem.h5 and summary.json checked
// against the checksums recorded when the entry was made: a damaged entry is refused,
// naming the file); otherwise calls run(tmp_dir, resume) to
// produce one in a temporary folder CACHE/<key>.tmp<pid> and renames it into place (a
// killed run leaves no entry). A killed run leaves its temporary folder with its last
// checkpoint: the next run of the same inputs takes that folder over and calls run with
// resume = true (continue from tmp_dir/checkpoint.h5) instead of starting again. A run
// that fails before its first checkpoint removes its temporary folder (and CACHE, if it
// created it and left it empty).
CachedDem cached_dem_run(const std::string& cache_dir, const std::string& key,
                         const std::function<void(const std::string& dir, bool resume)>& run);

// CACHE/<key>.tmp<pid> holding a checkpoint.h5 whose process <pid> no longer exists, or "".
std::string interrupted_dem_run(const std::string& cache_dir, const std::string& key);

}  // namespace centrec::runs
