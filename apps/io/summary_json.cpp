#include "io/summary_json.hpp"

#include "io/atomic_write.hpp"

namespace centrec::io {

void write_json_file(const std::string& path, const nlohmann::json& j) {
  // Invalid UTF-8 (in a path, say) is replaced rather than failing after the work is done.
  write_text_atomically(path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace centrec::io
