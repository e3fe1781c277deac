#pragma once
// Writes a summary.json atomically (temporary name, then rename; docs/outputs.md).
#include <nlohmann/json.hpp>
#include <string>

namespace centrec::io {

void write_json_file(const std::string& path, const nlohmann::json& j);

}  // namespace centrec::io
