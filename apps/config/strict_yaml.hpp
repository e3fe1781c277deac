#pragma once
// Strict YAML reading at the edge of the program (docs/architecture.md):
// every key read is checked for type and range, every key not read is an error,
// and every value actually used (given or defaulted) is recorded into a
// "resolved" tree that outputs echo.
#include <yaml-cpp/yaml.h>

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace centrec::config {

// A configuration error; the message names the file, line, key path, value and allowed range.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An allowed interval for a number. Open or closed ends.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  static Range any() { return {}; }
  bool contains(double v) const;
  std::string describe() const;
};

// Reader for one YAML mapping. Children share the file name and the resolved tree.
class MapReader {
 public:
  // Parses `path` as a YAML file; the root must be a mapping.
  static MapReader from_file(const std::string& path);
  // Parses YAML text (tests, inline cases); `source_name` appears in errors.
  static MapReader from_string(const std::string& text, const std::string& source_name = "<string>");

  bool has(const std::string& key) const;

  double number(const std::string& key, double default_value, Range range, const std::string& unit = "");
  double required_number(const std::string& key, Range range, const std::string& unit = "");
  long integer(const std::string& key, long default_value, long lo, long hi);
  bool boolean(const std::string& key, bool default_value);
  std::string string(const std::string& key, const std::string& default_value);
  std::string choice(const std::string& key, const std::string& default_value,
                     const std::vector<std::string>& allowed);
  std::array<double, 3> vec3(const std::string& key, const std::array<double, 3>& default_value,
                             const std::string& unit = "");
  std::vector<double> numbers(const std::string& key, const std::vector<double>& default_value,
                              Range range, const std::string& unit = "");

  // Child mapping; if absent, an empty mapping (so its defaults apply and are recorded).
  MapReader child(const std::string& key);
  // A sequence of mappings under key (empty if absent).
  std::vector<MapReader> children(const std::string& key);

  // Declares every key this mapping may hold (read or not, e.g. optional sections) and
  // refuses at once any other key, with the closest known key as a suggestion. finish()
  // then also accepts these.
  void known_keys(const std::vector<std::string>& keys);

  // Throws ConfigError naming the first key in this mapping that was never read (nor
  // declared by known_keys). Call once all keys of this mapping are read; child readers
  // check their own.
  void finish() const;

  // The full resolved configuration (all readers of this file share it).
  YAML::Node resolved() const { return shared_->resolved; }
  std::string resolved_text() const;
  const std::string& path() const { return path_; }
  const std::string& source() const { return shared_->source; }

  // Error with location for a value that passed type checks but violates a relation.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // The same for a dotted key path below this mapping ("dem.run.dt"): the line is the
  // deepest part of the path the file gives.
  [[noreturn]] void fail_path(const std::string& dotted, const std::string& message) const;

 private:
  struct Shared {
    std::string source;
    YAML::Node resolved;
  };
  MapReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared, YAML::Node resolved_here);
  std::string key_path(const std::string& key) const;
  std::string where(const YAML::Node& n) const;
  std::optional<YAML::Node> get(const std::string& key);
  double to_number(const std::string& key, const YAML::Node& n) const;
  void check_keys(const std::vector<std::string>& allowed) const;

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<Shared> shared_;
  YAML::Node resolved_here_;
  std::vector<std::string> used_;
  std::vector<std::string> known_;
};

// The candidate closest to `word` (case-insensitive edit distance, at most about a third
// of its letters), or "" if none is close: the "did you mean" of unknown keys and flags.
std::string closest_word(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace centrec::config
