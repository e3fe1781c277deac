#include "cli/case_overrides.hpp"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cli/command_line.hpp"
#include "config/shared_ranges.hpp"

namespace centrec::cli {

namespace {

// One override flag. It sets a case key (`key`), or the operating point (`point`: the
// receiver's, or the DEM drum's without one, config::effective_dem), or, with neither, any
// key (--set KEY=VALUE). A key's value is checked by the key's own reader when the case is
// read again with it; the operating point against the range the keys share.
struct Flag {
  const char* name;
  const char* value;     // the value's name in the usage
  const char* commands;  // the commands that take it, separated by spaces
  const char* help;
  const char* key = nullptr;
  std::optional<double> config::Overrides::*point = nullptr;
  config::Range range{};  // of `point`
  const char* unit = "";
};

const Flag kFlags[] = {
    {"--threads", "N", "dem run", "DEM threads (0 = all cores) instead of dem.run.threads", "dem.run.threads"},
    {"--duration", "SECONDS", "dem", "seconds of spin-up instead of dem.run.duration", "dem.run.duration"},
    {"--speed-rpm", "RPM", "run", "the receiver's speed (or, without one, the DEM drum's), rpm", nullptr,
     &config::Overrides::speed_rpm, config::shared_ranges::speed_rpm(), "rpm"},
    {"--mass-flow", "KG_S", "run", "the receiver's mass flow (or, without one, the DEM feeder's), kg/s", nullptr,
     &config::Overrides::mass_flow, config::shared_ranges::mass_flow(), "kg/s"},
    {"--seed", "N", "run", "the DEM's random seed instead of dem.seed (a replica of the same case)", "dem.seed"},
    {"--wall-rolling-model", "relative|liggghts", "dem export-liggghts",
     "dem.contacts.wall_rolling_model instead of the case's (liggghts: LIGGGHTS' form)",
     "dem.contacts.wall_rolling_model"},
    {"--set", "KEY=VALUE", "dem run sweep thermal operate",
     "any case key, as its dotted path (--set thermal.flux.q_film=3e5); repeatable"},
};

bool takes(const Flag& f, const std::string& command) {
  std::istringstream words(f.commands);
  for (std::string w; words >> w;)
    if (w == command) return true;
  return false;
}

// The row whose own flag sets `key`, or nullptr (then --set does).
const Flag* flag_of_key(const std::string& key) {
  for (const Flag& f : kFlags)
    if (f.key && key == f.key) return &f;
  return nullptr;
}
}  // namespace

void add_override_flags(CommandLine& app, config::Overrides& o, const std::string& command) {
  for (const Flag& f : kFlags) {
    if (!takes(f, command)) continue;
    CLI::Option* opt = nullptr;
    if (f.point) {
      const auto member = f.point;
      opt = app.add_option_function<double>(
                   f.name, [&o, member](const double& v) { o.*member = v; }, f.help)
                ->check(number_in(f.range, f.unit));
    } else if (f.key) {
      const std::string key = f.key;
      opt = app.add_option_function<std::string>(
          f.name, [&o, key](const std::string& v) { o.keys[key] = v; }, f.help);
    } else {
      opt = app.add_option_function<std::vector<std::string>>(
                   f.name,
                   [&o](const std::vector<std::string>& sets) {
                     for (const std::string& s : sets) {
                       const std::size_t eq = s.find('=');
                       o.keys[s.substr(0, eq)] = s.substr(eq + 1);
                     }
                   },
                   f.help)
                ->check(CLI::Validator(
                    [](std::string& s) {
                      return s.find('=') == std::string::npos || s.front() == '='
                                 ? "'" + s + "' is not KEY=VALUE (e.g. thermal.T_in=900)"
                                 : std::string();
                    },
                    "KEY=VALUE"))
                ->allow_extra_args(false);
    }
    opt->option_text(f.value);
  }
}

Args override_args(const config::Overrides& o, const std::string& command) {
  Args a;
  for (const Flag& f : kFlags) {
    if (f.point && o.*f.point) a.insert(a.end(), {f.name, shortest_text(*(o.*f.point))});
    if (f.key && o.sets(f.key) && takes(f, command)) a.insert(a.end(), {f.name, o.keys.at(f.key)});
  }
  for (const auto& [key, value] : o.keys) {
    const Flag* own = flag_of_key(key);
    if (!own || !takes(*own, command)) a.insert(a.end(), {"--set", key + "=" + value});
  }
  return a;
}

std::vector<std::string> override_flag_names() {
  std::vector<std::string> names;
  for (const Flag& f : kFlags) names.push_back(f.name);
  return names;
}

std::vector<std::string> override_keys(const std::string& command) {
  std::vector<std::string> keys;
  for (const Flag& f : kFlags)
    if (f.key && takes(f, command)) keys.push_back(f.key);
  return keys;
}

std::string flags_text(const config::Overrides& o, const std::string& command) {
  std::string s;
  for (const std::string& a : override_args(o, command)) s += (s.empty() ? "" : " ") + a;
  return s;
}

config::CaseFile checked_overrides(const config::CaseFile& cf, const config::Overrides& o, const std::string& command) {
  try {
    return config::with_overrides(cf, o);
  } catch (const config::ConfigError& e) {
    throw UsageError("with " + flags_text(o, command) + ": " + e.what());
  }
}

config::DemCase checked_dem(const config::CaseFile& cf, const config::Overrides& o, const std::string& command) {
  const config::ReceiverCase* receiver = cf.receiver ? &*cf.receiver : nullptr;
  config::DemCase dc;
  try {
    dc = config::effective_dem(*cf.dem, receiver, o);
  } catch (const std::invalid_argument& e) {
    throw UsageError("with " + flags_text(o, command) + ": " + e.what());
  }
  if (const auto p = config::dem_run_problem(dc, receiver && receiver->dem_diameter_d > 0.0))
    throw UsageError("with " + flags_text(o, command) + ": " + p->key + ": " + p->message);
  return dc;
}

}  // namespace centrec::cli
