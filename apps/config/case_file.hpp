#pragma once
// A YAML case file read into the typed configs of each library.
// Each top-level section has one reader (apps/case_<section>.cpp); a section
// that is absent is simply not configured, an unknown top-level key is an error.
#include <optional>
#include <string>
#include <vector>

#include "config/case_checks.hpp"
#include "config/case_dem.hpp"
#include "config/case_receiver.hpp"
#include "config/case_sweep.hpp"
#include "config/case_thermal.hpp"
#include "config/strict_yaml.hpp"

namespace centrec::config {

struct CaseFile {
  std::string path;
  std::string title;
  std::optional<DemCase> dem;            // as given, before any receiver derivation
  std::optional<ReceiverCase> receiver;  // the actual receiver of a coupled run (needs `dem`)
  std::optional<ThermalCase> thermal;  // `film` + `thermal` sections (film from the DEM if absent)
  std::optional<SweepSpec> sweep;        // the operating window of `centrec sweep`
  std::string resolved_yaml;  // the fully resolved configuration, echoed into outputs
};

// Reads and checks every section; throws ConfigError on the first problem.
CaseFile read_case_file(const std::string& path);
// The same from YAML text (a checkpoint's resolved configuration); `path` names the case
// in messages and anchors its relative paths.
CaseFile read_case_text(const std::string& text, const std::string& path);

// Reads YAML text as read_case_text does, appending a KeyRecord to `keys` for every key
// the readers are asked for (the key reference, apps/config/case_keys.hpp). On a
// ConfigError the keys read before it stay in `keys`.
CaseFile read_case_recording(const std::string& text, const std::string& path, std::vector<KeyRecord>& keys);

// The case with the overrides' keys (dotted paths into any section the case has) written
// into its resolved configuration and read again, so every value passes its key's own checks
// and the resolved configuration that outputs and checkpoints record holds what the run does
// (the operating point is effective_dem's). Throws ConfigError (a key of a section the case
// lacks, an unknown key, a value out of its range).
CaseFile with_overrides(const CaseFile& cf, const Overrides& o);

// The value of a dotted key path in the case's resolved configuration, as its text ("" when
// the configuration does not hold it).
std::string resolved_value(const CaseFile& cf, const std::string& dotted);

// The shortest decimal text (at least 6 significant digits) that reads back as v: how a
// command-line value is written into a resolved case and into a child process's arguments.
std::string shortest_text(double v);

}  // namespace centrec::config
