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
  app.add_option("--wall-rolling-model", o.wall_rolling_model,
                 "overrides contacts.wall_rolling_model (liggghts: LIGGGHTS' form)")
      ->option_text("relative|liggghts");
}

void apply_wall_rolling_model(config::DemCase& dc, const std::string& model) {
  if (model == "relative") dc.scene.wall_rolling = dem::WallRolling::relative;
  else if (model == "liggghts") dc.scene.wall_rolling = dem::WallRolling::liggghts;
  else throw std::invalid_argument("--wall-rolling-model must be relative or liggghts, not " + model);
}

}  // namespace centrec::cli
