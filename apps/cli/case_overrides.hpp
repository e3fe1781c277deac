#pragma once
// Command-line values that replace a case's (--threads, --duration, --speed-rpm,
// --mass-flow, --seed, --wall-rolling-model) pass the same checks as the case file's values
// (config/case_checks), before any work; a refusal names the flags. A child process
// (`centrec sweep`'s points, `centrec run --replicas`) is given them by override_args.
#include <initializer_list>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "config/case_file.hpp"

namespace centrec::cli {

// The flags that replace a case value, each declared once (name, help, range, the
// config::Overrides member it sets) in case_overrides.cpp.
enum class OverrideFlag { threads, duration, speed_rpm, mass_flow, seed, wall_rolling_model };

// Declares `which` on `app`, each setting its member of `o` when given.
void add_override_flags(CommandLine& app, config::Overrides& o, std::initializer_list<OverrideFlag> which);

// {"--threads", "2", "--duration", "0.1"}: the given overrides as arguments, each value
// written so that it reads back as itself.
Args override_args(const config::Overrides& o);
// Every override flag's name ("--threads", ...): what a child's command line sets anew.
std::vector<std::string> override_flag_names();

// "--threads 2 --duration 0.1": the overrides as they were given.
std::string flags_text(const config::Overrides& o);

// config::with_overrides, its ConfigError turned into a UsageError naming the flags.
config::CaseFile checked_overrides(const config::CaseFile& cf, const config::Overrides& o);

// The DEM a coupled run simulates with the overrides, checked (config::dem_run_problem).
config::DemCase checked_dem(const config::CaseFile& cf, const config::Overrides& o);

}  // namespace centrec::cli
