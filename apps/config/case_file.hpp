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

// The case with the overrides that are keys of its `dem:` section (run.threads,
// run.duration, seed, contacts.wall_rolling_model) written into it, read again (and so
// checked again): the resolved configuration that outputs and checkpoints record holds
// what the run actually does (effective_dem applies them to the DEM). Throws ConfigError.
CaseFile with_overrides(const CaseFile& cf, const Overrides& o);

}  // namespace centrec::config
