#include "runs/settled_start.hpp"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "config/case_checks.hpp"
#include "config/case_thermal.hpp"
#include "dem/scene/settled_start.hpp"
#include "io/checkpoint_h5.hpp"

namespace centrec::runs {

std::vector<dem::scene::InitialFilmSpec::Particle> settled_start(const config::CaseFile& cf, const config::DemCase& dc) {
  std::string dir = dc.initial_film_from_run;
  const std::string case_dir = config::case_directory(cf.path);
  if (!dir.empty() && dir[0] != '/' && !case_dir.empty()) dir = case_dir + "/" + dir;
  try {
    const io::RunCheckpoint ck = io::read_checkpoint(dir);
    // Only the run's drum matters here (its dem: and receiver: sections): its other
    // sections may hold keys of another version of this program.
    YAML::Node all = YAML::Load(ck.resolved_yaml), drum;
    for (const char* key : {"dem", "receiver"})
      if (all[key]) drum[key] = all[key];
    YAML::Emitter text;
    text << drum;
    const config::CaseFile source = config::read_case_text(text.c_str(), ck.case_path);
    if (!source.dem) throw std::invalid_argument("its case has no dem: section");
    const config::DemCase sd = config::effective_dem(*source.dem, source.receiver ? &*source.receiver : nullptr, {});
    return dem::scene::settled_film(sd.scene, ck.scene.engine, dc.scene);
  } catch (const std::exception& e) {
    throw config::ConfigError(cf.path + ": dem.initial_film.from_run = " + dc.initial_film_from_run + " (" + dir +
                              "): " + e.what());
  }
}

}  // namespace centrec::runs
