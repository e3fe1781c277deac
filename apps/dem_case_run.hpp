#pragma once
// One DEM run of a case (the body of `centrec dem`), shared with the coupled `centrec run`.
#include <optional>
#include <string>

#include "case_file.hpp"
#include "checkpoint_h5.hpp"

namespace centrec::cli {

// Runs `dc` (the case's DEM section, possibly adjusted by the caller), from the checkpoint
// `ck` when given, and writes out_dir/{summary.json, dem.h5, dem.xmf, mass_flow.csv}
// (apps/dem_run_report) and its checkpoints (run.checkpoint_interval).
void run_dem_case(const CaseFile& cf, const DemCase& dc, const std::string& out_dir,
                  const std::optional<RunCheckpoint>& ck = std::nullopt);

}  // namespace centrec::cli
