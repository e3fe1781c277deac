#pragma once
// `centrec paths`: a fed drum's residence-time distribution from its particle tracks and its
// particles heated along their own paths by a coupled run's thermal solution
// (docs/particle_paths.md).
#include <string>

#include <nlohmann/json.hpp>

#include "config/case_thermal.hpp"

namespace centrec::runs {

// dem_dir: a `centrec dem` run of a fed drum (summary.json, tracks/); results_h5: the
// results.h5 of a `centrec run` on that drum's film (its /grid, /steady and /coupling);
// tc: the thermal case of that run (T_in, material, c_p). Writes out_dir/paths.csv (one row
// per weighted path) and returns the summary (also printed).
nlohmann::json particle_paths_report(const std::string& dem_dir, const std::string& results_h5,
                                     const config::ThermalCase& tc, const std::string& out_dir);

}  // namespace centrec::runs
