#pragma once
// Writes a summary.json atomically (temporary name, then rename; docs/outputs.md), and
// reads one back.
#include <nlohmann/json.hpp>
#include <string>

namespace centrec::io {

void write_json_file(const std::string& path, const nlohmann::json& j);

// Throws std::runtime_error naming the file when it is missing or not JSON.
nlohmann::json read_json_file(const std::string& path);

}  // namespace centrec::io
