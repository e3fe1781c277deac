#pragma once
// One DEM run of a case (the body of `centrec dem`), shared with the coupled `centrec run`.
#include <optional>
#include <string>

#include "config/case_file.hpp"
#include "io/checkpoint_h5.hpp"

namespace centrec::runs {

// Runs `dc` (the case's DEM section, possibly adjusted by the caller), from the checkpoint
// `ck` when given, and writes out_dir/{summary.json, dem.h5, dem.xmf, mass_flow.csv}
// (apps/runs/dem_run_report) and its checkpoints (run.checkpoint_interval).
void run_dem_case(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                  const std::optional<io::RunCheckpoint>& ck = std::nullopt);

}  // namespace centrec::runs
