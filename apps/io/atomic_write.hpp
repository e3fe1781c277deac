#pragma once
// Outputs are written to a temporary name and renamed into place, so a killed run
// never leaves a half-written file under the final name (docs/outputs.md).
#include <string>

namespace centrec::io {

void write_text_atomically(const std::string& path, const std::string& text);

// Creates the directory (and parents); throws std::runtime_error naming it on failure.
void ensure_directory(const std::string& dir);

// Checksum of a file's bytes (16 hex digits, FNV-1a 64); throws naming the file if unreadable.
std::string file_checksum(const std::string& path);

// An output folder made ready before any work (docs/reliability.md): created with its
// parents and proven writable by writing and removing a probe file, so an unwritable
// --out is refused at once instead of after the solve. A folder this object created is
// removed again when it is destroyed still empty (a run that failed before writing).
class OutputFolder {
 public:
  explicit OutputFolder(std::string dir);  // throws std::runtime_error naming dir and the reason
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  const std::string& path() const { return dir_; }

 private:
  std::string dir_;
  std::string created_;  // the top-most folder this object created ("" = none)
};

}  // namespace centrec::io
