#pragma once
// One DEM run of a case (the body of `centrec dem`, and the DEM of the coupled `centrec run`).
// An engine runs the DEM and returns the engine-neutral io::DemRunResult; run_dem_case
// writes it out the same way whichever engine made it (native here, LIGGGHTS in
// apps/liggghts/dem_liggghts_run).
#include <functional>
#include <optional>
#include <string>

#include "config/case_file.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/dem_run_result.hpp"

namespace centrec::runs {

// Runs `dc` (the case's DEM section, possibly adjusted by the caller) with out_dir as its
// working folder and returns the result.
using DemEngine = std::function<io::DemRunResult(const config::CaseFile& cf, const config::DemCase& dc,
                                                 const std::string& out_dir)>;

// The native engine (runs/dem_run.hpp), from the checkpoint `ck` when given; writes
// out_dir/checkpoint.h5 every run.checkpoint_interval of wall time.
DemEngine native_engine(const std::optional<io::RunCheckpoint>& ck = std::nullopt);

// Runs `engine`, writes out_dir/{summary.json, dem.h5, dem.xmf, mass_flow.csv}
// (apps/runs/dem_run_report) and returns the result.
io::DemRunResult run_dem_case(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                  const DemEngine& engine);

}  // namespace centrec::runs
