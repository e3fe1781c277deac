#include "cli/dem_engine_options.hpp"

#include <stdexcept>

namespace centrec::cli {

void add_engine_options(CLI::App& app, DemEngineOptions& o) {
  app.add_option("--engine", o.engine)->check(CLI::IsMember({"centrec", "liggghts"}));
  app.add_option("--ranks", o.ranks)->check(positive_number());
  app.add_option("--mpirun", o.mpirun);
  app.add_option("--liggghts", o.liggghts);
  app.add_option("--wall-rolling-model", o.wall_rolling_model);
}

void apply_wall_rolling_model(config::DemCase& dc, const std::string& model) {
  if (model == "relative") dc.scene.wall_rolling = dem::WallRolling::relative;
  else if (model == "liggghts") dc.scene.wall_rolling = dem::WallRolling::liggghts;
  else throw std::invalid_argument("--wall-rolling-model must be relative or liggghts, not " + model);
}

}  // namespace centrec::cli
