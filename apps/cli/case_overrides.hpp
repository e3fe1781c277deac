#pragma once
// Command-line values that replace a case's: each flag declared once, as a row of the table in
// case_overrides.cpp (its name, the case key it sets or the operating point, the commands that
// take it, its help). A case key given on the command line (--threads, --seed, --set KEY=VALUE)
// is written into the case and read again by the key's own reader (config::with_overrides),
// before any work; a refusal names the flags. A child process (`centrec sweep`'s points,
// `centrec run --replicas`) is given them by override_args.
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "config/case_file.hpp"

namespace centrec::cli {

// Declares on `app` every override flag that `command` ("dem", "run", ...) takes, each
// setting its part of `o` when given.
void add_override_flags(CommandLine& app, config::Overrides& o, const std::string& command);

// {"--threads", "2", "--set", "thermal.T_in=900"}: the given overrides as arguments to
// `command` (a key with a flag of its own that `command` takes by that flag, any other by
// --set), each value written so that it reads back as itself.
Args override_args(const config::Overrides& o, const std::string& command);
// Every override flag's name ("--threads", ..., "--set"): what a child's command line sets anew.
std::vector<std::string> override_flag_names();

// The case keys that `command`'s own flags set ("dem.run.threads", ...; --set's aside).
std::vector<std::string> override_keys(const std::string& command);

// A value as flags_text and override_args write it (config/case_file.hpp).
using config::shortest_text;

// "--threads 2 --set thermal.T_in=900": the overrides as `command` takes them (override_args).
std::string flags_text(const config::Overrides& o, const std::string& command);

// The case with the overrides' keys (config::with_overrides), its ConfigError turned into a
// UsageError naming the flags as `command` takes them.
config::CaseFile checked_overrides(const config::CaseFile& cf, const config::Overrides& o, const std::string& command);

// The DEM a run simulates with the overrides' operating point, checked
// (config::dem_run_problem); `cf` has the overrides' keys already (checked_overrides).
config::DemCase checked_dem(const config::CaseFile& cf, const config::Overrides& o, const std::string& command);

}  // namespace centrec::cli
