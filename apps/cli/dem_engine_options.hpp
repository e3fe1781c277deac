#pragma once
// The engine choice of `centrec dem` (--engine centrec|liggghts, --ranks, --mpirun,
// --liggghts).
#include <string>

#include "cli/command_line.hpp"
#include "config/case_dem.hpp"

namespace centrec::cli {

struct DemEngineOptions {
  std::string engine = "centrec";     // centrec (native) or liggghts
  int ranks = 1;                      // MPI ranks (liggghts)
  std::string mpirun = "mpirun";      // launcher (liggghts), e.g. srun on a cluster
  std::string liggghts = "liggghts";  // executable (liggghts)
};

// Declares the options above on a command's parser.
void add_engine_options(CLI::App& app, DemEngineOptions& o);

}  // namespace centrec::cli
