#pragma once
// Scratch directories and case files for tests that run a command end to end.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace centrec::testing {

// An empty directory unique to this test process: <tmp>/centrec_test_<name>_<pid>.
inline std::string temp_dir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("centrec_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(p);
  return p.string();
}

// Like temp_dir, but emptied first (for tests that check what a run wrote).
inline std::string fresh_dir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("centrec_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

// Writes `text` to dir/case.yaml and returns that path.
inline std::string write_case(const std::string& dir, const std::string& text) {
  const std::string path = dir + "/case.yaml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace centrec::testing
