#include "cli/dem_engine_options.hpp"

#include <stdexcept>

namespace centrec::cli {

void add_engine_options(CLI::App& app, DemEngineOptions& o) {
  app.add_option("--engine", o.engine, "the DEM engine: centrec (native) or liggghts (LIGGGHTS 3.8)")
      ->check(CLI::IsMember({"centrec", "liggghts"}))
      ->option_text("centrec|liggghts");
  app.add_option("--ranks", o.ranks, "MPI ranks of a LIGGGHTS run")->check(positive_number())->option_text("N");
  app.add_option("--mpirun", o.mpirun, "the MPI launcher of a LIGGGHTS run (srun on a cluster)")->option_text("CMD");
  app.add_option("--liggghts", o.liggghts, "the LIGGGHTS executable")->option_text("EXE");
}

}  // namespace centrec::cli
