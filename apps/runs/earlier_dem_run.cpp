#include "runs/earlier_dem_run.hpp"

#include <filesystem>
#include <cstdlib>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>

#include "io/summary_json.hpp"
#include "runs/dem_inputs.hpp"

namespace centrec::runs {

nlohmann::json earlier_dem_run_summary(const std::string& case_resolved_yaml, const std::string& dir) {
  for (const char* file : {"dem.h5", "summary.json"})
    if (!std::filesystem::exists(dir + "/" + file))
      throw std::invalid_argument(dir + " has no " + file +
                                  ": --dem-from takes the folder of a finished `centrec dem` run");
  nlohmann::json summary = io::read_json_file(dir + "/summary.json");
  if (!summary.contains("resolved_config") || !summary["resolved_config"].is_string())
    throw std::invalid_argument(dir + "/summary.json has no resolved_config: not a `centrec dem` run's summary");
  auto mine = dem_input_values(case_resolved_yaml, {"dem", "receiver"}),
       theirs = dem_input_values(summary["resolved_config"].get<std::string>(), {"dem", "receiver"});
  // A receiver enters the DEM only when it derives the DEM drum (receiver.dem_diameter_d > 0,
  // docs/scaling.md); otherwise it scales the thermal film only, so a drum run without one
  // serves a case that scales it up.
  auto derives = [](const std::map<std::string, std::string>& m) {
    const auto it = m.find("receiver.dem_diameter_d");
    return it != m.end() && std::strtod(it->second.c_str(), nullptr) > 0.0;
  };
  if (!derives(mine) && !derives(theirs))
    for (auto* m : {&mine, &theirs})
      for (auto it = m->begin(); it != m->end();) it = it->first.rfind("receiver.", 0) == 0 ? m->erase(it) : std::next(it);
  std::string differ;
  auto value = [](const std::map<std::string, std::string>& m, const std::string& k) {
    const auto it = m.find(k);
    return it == m.end() ? std::string("(absent)") : it->second;
  };
  std::set<std::string> keys;
  for (const auto& kv : mine) keys.insert(kv.first);
  for (const auto& kv : theirs) keys.insert(kv.first);
  for (const auto& key : keys) {
    const std::string a = value(mine, key), b = value(theirs, key);
    if (a != b) differ += "\n  " + key + ": " + a + " here, " + b + " in that run";
  }
  if (!differ.empty())
    throw std::invalid_argument("the DEM run in " + dir + " is not of this case's DEM inputs:" + differ +
                                "\nrun the DEM of this case (without --dem-from), or give the case that run used");
  return summary;
}

}  // namespace centrec::runs
