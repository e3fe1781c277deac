#pragma once
// The outputs of a DEM run, whichever engine produced it (native or LIGGGHTS):
// DIR/summary.json, DIR/dem.h5 + DIR/dem.xmf, DIR/mass_flow.csv and the closing
// lines on stdout. The engine fills a DemRunResult; everything downstream is shared,
// so both engines write the same keys.
#include <string>
#include <utility>
#include <vector>

#include "case_dem.hpp"
#include "case_file.hpp"
#include "dem_run_result.hpp"

namespace centrec::cli {


// Mass flow over the last `window` seconds of the log, kg/s: {fed, out}.
std::pair<double, double> recent_flows(const std::vector<dem::scene::MassFlowSample>& log, double window);

// Writes summary.json, dem.h5, dem.xmf and mass_flow.csv into out_dir and prints the summary lines.
void write_dem_run_report(const std::string& out_dir, const CaseFile& cf, const DemCase& dc, const DemRunResult& r);

}  // namespace centrec::cli
