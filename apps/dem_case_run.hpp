#pragma once
// One DEM run of a case (the body of `centrec dem`), shared with the coupled `centrec run`.
#include <string>

#include "case_file.hpp"

namespace centrec::cli {

// Runs `dc` (the case's DEM section, possibly adjusted by the caller) and writes
// out_dir/{summary.json, dem.h5, dem.xmf, mass_flow.csv} (apps/dem_run_report).
void run_dem_case(const CaseFile& cf, const DemCase& dc, const std::string& out_dir);

}  // namespace centrec::cli
