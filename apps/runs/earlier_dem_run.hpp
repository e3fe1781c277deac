#pragma once
// An earlier DEM-only run (`centrec dem CASE --out DIR`) as the DEM of a coupled run
// (`centrec run CASE --dem-from DIR`): the film is read back from DIR/dem.h5 instead of
// running the DEM again or looking in the cache. The run must be of the same DEM inputs:
// the case's resolved `dem:` and `receiver:` sections (the receiver derives the drum and its
// flow) against the ones DIR/summary.json recorded, less the keys that do not change a
// DEM's results (thread count, progress and checkpoint intervals: the engine is bitwise the
// same at any thread count).
#include <nlohmann/json.hpp>
#include <string>

namespace centrec::runs {

// DIR/summary.json of a finished run of the same DEM inputs as the case whose resolved
// configuration is `case_resolved_yaml`. Throws std::invalid_argument naming the missing
// file, or every key whose value differs (case value against the run's).
nlohmann::json earlier_dem_run_summary(const std::string& case_resolved_yaml, const std::string& dir);

}  // namespace centrec::runs
