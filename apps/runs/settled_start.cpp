#include "runs/settled_start.hpp"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "config/case_checks.hpp"
#include "config/case_thermal.hpp"
#include "dem/scene/settled_start.hpp"
#include "io/checkpoint_h5.hpp"

namespace centrec::runs {

config::CaseFile drum_case_of(const io::RunCheckpoint& ck) {
  YAML::Node all = YAML::Load(ck.resolved_yaml), drum;
  for (const char* key : {"dem", "receiver"})
    if (all[key]) drum[key] = all[key];
  YAML::Emitter text;
  text << drum;
  config::CaseFile cf = config::read_case_text(text.c_str(), ck.case_path);
  if (!cf.dem) throw std::invalid_argument(ck.case_path + ": the checkpoint's case has no dem: section");
  return cf;
}

dem::scene::InitialFilmSpec settled_start(const config::CaseFile& cf, const config::DemCase& dc) {
  const std::string dir = config::settled_start_dir(cf.path, dc);
  try {
    const io::RunCheckpoint ck = io::read_checkpoint(dir);
    const config::CaseFile source = drum_case_of(ck);
    const config::DemCase sd = config::effective_dem(*source.dem, source.receiver ? &*source.receiver : nullptr, {});
    return dem::scene::settled_film(sd.scene, ck.scene.engine, dc.scene);
  } catch (const std::exception& e) {
    throw config::ConfigError(cf.path + ": dem.initial_film.from_run = " + dc.initial_film_from_run + " (" + dir +
                              "): " + e.what());
  }
}

}  // namespace centrec::runs
