#pragma once
// `centrec dem CASE.yaml --engine liggghts`: exports the case (liggghts_export), runs
// LIGGGHTS under MPI, shows progress from its mass-flow record, and reads the film dumps
// into the same SceneSampler as the native engine as they appear. The result goes to the
// shared outputs (dem_run_report). A failure (missing launcher or binary, an ERROR in the
// log, a non-zero exit, lost atoms) is reported with the relevant log lines.
#include <string>

#include "config/case_dem.hpp"
#include "config/case_file.hpp"
#include "io/dem_run_result.hpp"
#include "liggghts/liggghts_launch.hpp"
#include "runs/dem_case_run.hpp"

namespace centrec::liggghts {

// The deck's mass-flow record (fix print lines "time fed out holdup particles", cumulative
// kg), or with `prefix` the lines of a log that start with it. lost = the mass balance's
// remainder (initial holdup + fed - out - holdup): atoms that left through the box.
std::vector<dem::scene::MassFlowSample> read_liggghts_mass_flow(const std::string& path, double initial_holdup,
                                                                 const std::string& prefix = "");

// Runs the case in out_dir/liggghts (deck, data, STL, log, dumps) and returns the result.
// `launch.ranks`, `launch.mpirun` and `launch.liggghts` are used; paths are filled in.
io::DemRunResult run_dem_on_liggghts(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                                 LiggghtsLaunch launch);
// The same as an engine of runs::run_dem_case.
runs::DemEngine liggghts_engine(const LiggghtsLaunch& launch);

}  // namespace centrec::liggghts
