#include "runs/dem_inputs.hpp"

#include <yaml-cpp/yaml.h>

namespace centrec::runs {

namespace {
bool changes_no_result(const std::string& key) {
  return key == "dem.run.threads" || key == "dem.run.progress_interval" || key == "dem.run.checkpoint_interval";
}

void collect(const YAML::Node& node, const std::string& path, std::map<std::string, std::string>& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) collect(kv.second, path + "." + kv.first.as<std::string>(), out);
  } else if (node.IsSequence()) {
    for (std::size_t k = 0; k < node.size(); ++k) collect(node[k], path + "[" + std::to_string(k) + "]", out);
  } else if (!changes_no_result(path)) {
    out[path] = node.IsNull() ? "(none)" : node.as<std::string>();
  }
}
}  // namespace

std::map<std::string, std::string> dem_input_values(const std::string& resolved_yaml,
                                                    std::initializer_list<const char*> sections) {
  const YAML::Node root = YAML::Load(resolved_yaml);
  std::map<std::string, std::string> keys;
  for (const char* section : sections)
    if (root[section]) collect(root[section], section, keys);
  return keys;
}

}  // namespace centrec::runs
