#include "io/summary_json.hpp"

#include <fstream>
#include <stdexcept>

#include "io/atomic_write.hpp"

namespace centrec::io {

void write_json_file(const std::string& path, const nlohmann::json& j) {
  // Invalid UTF-8 (in a path, say) is replaced rather than failing after the work is done.
  write_text_atomically(path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + " is not valid JSON: " + e.what());
  }
}

}  // namespace centrec::io
