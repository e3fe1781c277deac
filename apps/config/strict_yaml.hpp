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

// One key as a reader declares it. A reader that records (MapReader::record_keys) notes
// every key it is asked for, read or defaulted: the case-key reference docs/case_keys.md is
// made from these records, so it comes from the readers themselves (apps/config/case_keys.cpp).
struct KeyRecord {
  std::string path;           // dotted key path, e.g. dem.drum.diameter
  std::string type;           // number, integer, boolean, text, choice, list of numbers, 3-vector, section
  std::string default_value;  // as the resolved configuration writes it; "required" when there is none
  std::string allowed;        // range or choices
  std::string unit;           // as the reader states it ("" = dimensionless or none)
  std::string meaning;        // one line, given at the reader
};

// Reader for one YAML mapping. Children share the file name and the resolved tree.
// Every typed read takes a last argument `meaning`: one line on what the key does, which
// the key reference prints (readers of case files give it for every key).
class MapReader {
 public:
  // Parses `path` as a YAML file; the root must be a mapping.
  static MapReader from_file(const std::string& path);
  // Parses YAML text (tests, inline cases); `source_name` appears in errors.
  static MapReader from_string(const std::string& text, const std::string& source_name = "<string>");

  bool has(const std::string& key) const;

  double number(const std::string& key, double default_value, Range range, const std::string& unit = "",
                const std::string& meaning = "");
  double required_number(const std::string& key, Range range, const std::string& unit = "",
                         const std::string& meaning = "");
  long integer(const std::string& key, long default_value, long lo, long hi, const std::string& meaning = "");
  bool boolean(const std::string& key, bool default_value, const std::string& meaning = "");
  std::string string(const std::string& key, const std::string& default_value, const std::string& meaning = "");
  std::string choice(const std::string& key, const std::string& default_value,
                     const std::vector<std::string>& allowed, const std::string& meaning = "");
  std::array<double, 3> vec3(const std::string& key, const std::array<double, 3>& default_value,
                             const std::string& unit = "", const std::string& meaning = "");
  std::vector<double> numbers(const std::string& key, const std::vector<double>& default_value,
                              Range range, const std::string& unit = "", const std::string& meaning = "");

  // Child mapping; if absent, an empty mapping (so its defaults apply and are recorded).
  MapReader child(const std::string& key, const std::string& meaning = "");
  // A sequence of mappings under key (empty if absent).
  std::vector<MapReader> children(const std::string& key, const std::string& meaning = "");

  // From now on this reader and every reader sharing its file append a KeyRecord to `into`
  // for each key they are asked for (the first time per key path); `into` must outlive them.
  void record_keys(std::vector<KeyRecord>* into) { shared_->recorder = into; }

  // Declares every key this mapping may hold (read or not, e.g. optional sections) and
  // refuses at once any other key, with the closest known key as a suggestion. finish()
  // then also accepts these.
  void known_keys(const std::vector<std::string>& keys);

  // Throws ConfigError naming the first key in this mapping that was never read (nor
  // declared by known_keys). Call once all keys of this mapping are read; child readers
  // check their own.
  void finish() const;

  // Takes `key` out of the resolved configuration: its value is derived from another
  // section (receiver.dem_diameter_d derives dem.drum), so echoing the reader's default
  // would misstate the run, and reading the echo back would count it as given.
  void drop_resolved(const std::string& key) { resolved_here_.remove(key); }

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
    std::vector<KeyRecord>* recorder = nullptr;  // record_keys()
  };
  MapReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared, YAML::Node resolved_here);
  std::string key_path(const std::string& key) const;
  std::string where(const YAML::Node& n) const;
  std::optional<YAML::Node> get(const std::string& key);
  double to_number(const std::string& key, const YAML::Node& n) const;
  void check_keys(const std::vector<std::string>& allowed) const;
  void note(const std::string& key, const std::string& type, const std::string& default_value,
            const std::string& allowed, const std::string& unit, const std::string& meaning) const;

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
