#include "cli/dem_engine_options.hpp"

#include <stdexcept>

namespace centrec::cli {

bool parse_engine_option(const Args& args, std::size_t& i, DemEngineOptions& o) {
  const std::string& a = args[i];
  auto value = [&]() -> std::string {
    if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
    return args[++i];
  };
  if (a == "--engine") {
    o.engine = value();
    if (o.engine != "centrec" && o.engine != "liggghts")
      throw std::invalid_argument("--engine must be centrec or liggghts, not " + o.engine);
  } else if (a == "--ranks") {
    o.ranks = std::stoi(value());
    if (o.ranks < 1) throw std::invalid_argument("--ranks must be at least 1");
  } else if (a == "--mpirun") {
    o.mpirun = value();
  } else if (a == "--liggghts") {
    o.liggghts = value();
  } else if (a == "--wall-rolling-model") {
    o.wall_rolling_model = value();
  } else {
    return false;
  }
  return true;
}

void apply_wall_rolling_model(config::DemCase& dc, const std::string& model) {
  if (model == "relative") dc.scene.wall_rolling = dem::WallRolling::relative;
  else if (model == "liggghts") dc.scene.wall_rolling = dem::WallRolling::liggghts;
  else throw std::invalid_argument("--wall-rolling-model must be relative or liggghts, not " + model);
}

}  // namespace centrec::cli
