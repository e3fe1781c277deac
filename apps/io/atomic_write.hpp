#pragma once
// Outputs are written to a temporary name and renamed into place, so a killed run
// never leaves a half-written file under the final name (docs/outputs.md).
#include <string>

namespace centrec::io {

void write_text_atomically(const std::string& path, const std::string& text);

// Creates the directory (and parents); throws std::runtime_error naming it on failure.
void ensure_directory(const std::string& dir);

}  // namespace centrec::io
