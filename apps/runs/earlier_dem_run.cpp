#include "runs/earlier_dem_run.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "io/summary_json.hpp"

namespace centrec::runs {

namespace {
// Keys that choose how a DEM runs, not what it computes.
bool changes_no_result(const std::string& key) {
  return key == "dem.run.threads" || key == "dem.run.progress_interval" || key == "dem.run.checkpoint_interval";
}

// Every scalar under the DEM-input sections as "section.key.subkey" -> value text.
void collect(const YAML::Node& node, const std::string& path, std::map<std::string, std::string>& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) collect(kv.second, path + "." + kv.first.as<std::string>(), out);
  } else if (node.IsSequence()) {
    for (std::size_t k = 0; k < node.size(); ++k) collect(node[k], path + "[" + std::to_string(k) + "]", out);
  } else if (!changes_no_result(path)) {
    out[path] = node.IsNull() ? "(none)" : node.as<std::string>();
  }
}

std::map<std::string, std::string> dem_inputs(const std::string& resolved_yaml) {
  const YAML::Node root = YAML::Load(resolved_yaml);
  std::map<std::string, std::string> keys;
  for (const char* section : {"dem", "receiver"})
    if (root[section]) collect(root[section], section, keys);
  return keys;
}
}  // namespace

nlohmann::json earlier_dem_run_summary(const std::string& case_resolved_yaml, const std::string& dir) {
  for (const char* file : {"dem.h5", "summary.json"})
    if (!std::filesystem::exists(dir + "/" + file))
      throw std::invalid_argument(dir + " has no " + file +
                                  ": --dem-from takes the folder of a finished `centrec dem` run");
  nlohmann::json summary = io::read_json_file(dir + "/summary.json");
  if (!summary.contains("resolved_config") || !summary["resolved_config"].is_string())
    throw std::invalid_argument(dir + "/summary.json has no resolved_config: not a `centrec dem` run's summary");
  const auto mine = dem_inputs(case_resolved_yaml), theirs = dem_inputs(summary["resolved_config"].get<std::string>());
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
