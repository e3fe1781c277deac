#include "io/summary_json.hpp"

#include "io/atomic_write.hpp"

namespace centrec::io {

void write_json_file(const std::string& path, const nlohmann::json& j) {
  write_text_atomically(path, j.dump(2) + "\n");
}

}  // namespace centrec::io
