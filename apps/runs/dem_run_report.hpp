#pragma once
// The outputs of a DEM run, whichever engine produced it (native or LIGGGHTS):
// DIR/summary.json, DIR/dem.h5 + DIR/dem.xmf, DIR/mass_flow.csv and the closing
// lines on stdout. The engine fills a DemRunResult; everything downstream is shared,
// so both engines write the same keys.
#include <string>
#include <utility>
#include <vector>

#include "config/case_dem.hpp"
#include "config/case_file.hpp"
#include "io/dem_run_result.hpp"

namespace centrec::runs {

// Writes summary.json, dem.h5, dem.xmf and mass_flow.csv into out_dir and prints the summary lines.
void write_dem_run_report(const std::string& out_dir, const config::CaseFile& cf, const config::DemCase& dc, const io::DemRunResult& r);

}  // namespace centrec::runs
