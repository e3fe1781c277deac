#include "runs/provenance.hpp"

#include <yaml-cpp/yaml.h>

#include "config/case_thermal.hpp"

namespace centrec::runs {

io::Provenance case_provenance(const std::string& case_path, const std::string& resolved_yaml) {
  io::Provenance p{case_path, resolved_yaml, {}};
  if (!case_path.empty()) p.input_files.push_back(case_path);
  try {
    const YAML::Node thermal = YAML::Load(resolved_yaml)["thermal"];
    const std::string dir = config::case_directory(case_path);
    for (const auto& [section, key] : {std::pair<const char*, const char*>{"film", "file"}, {"flux", "table_file"}}) {
      const YAML::Node v = thermal ? thermal[section][key] : YAML::Node();
      if (!v || !v.IsScalar() || v.as<std::string>().empty()) continue;
      const std::string f = v.as<std::string>();
      p.input_files.push_back(f[0] == '/' || dir.empty() ? f : dir + "/" + f);
    }
  } catch (const YAML::Exception&) {
    // The resolved configuration was parsed before the run; nothing more to hash.
  }
  return p;
}

}  // namespace centrec::runs
