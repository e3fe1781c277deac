#pragma once
// The engine choice of `centrec dem` (--engine centrec|liggghts, --ranks, --mpirun,
// --liggghts) and the --wall-rolling-model override shared with export-liggghts.
#include <string>

#include "cli/command_line.hpp"
#include "config/case_dem.hpp"

namespace centrec::cli {

struct DemEngineOptions {
  std::string engine = "centrec";     // centrec (native) or liggghts
  int ranks = 1;                      // MPI ranks (liggghts)
  std::string mpirun = "mpirun";      // launcher (liggghts), e.g. srun on a cluster
  std::string liggghts = "liggghts";  // executable (liggghts)
  std::string wall_rolling_model;     // empty = from the case
};

// Declares the options above on a command's parser.
void add_engine_options(CLI::App& app, DemEngineOptions& o);

// Sets contacts.wall_rolling_model ("relative" or "liggghts") on the case.
void apply_wall_rolling_model(config::DemCase& dc, const std::string& model);

}  // namespace centrec::cli
