#include "cli/case_overrides.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "cli/command_line.hpp"
#include "config/shared_ranges.hpp"

namespace centrec::cli {

namespace {
// A value as flags_text and override_args write it: the shortest text (at least 6
// significant digits) that reads back as v, so a child process gets the value itself.
std::string text(double v) {
  char b[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}
std::string text(long long v) { return std::to_string(v); }
const char* text(dem::WallRolling w) { return w == dem::WallRolling::relative ? "relative" : "liggghts"; }

struct Flag {
  OverrideFlag which;
  const char* name;
  const char* value;  // the value's name in the usage
  const char* help;
  CLI::Option* (*add)(CommandLine& app, config::Overrides& o, const char* name, const char* help);
  std::string (*given)(const config::Overrides& o);  // the value as given, "" = not given
};

// The ranges are the keys' own (config/shared_ranges.hpp); the case checks then see the value
// as the case's own.
const Flag kFlags[] = {
    {OverrideFlag::threads, "--threads", "N", "DEM threads (0-1024, 0 = all cores) instead of dem.run.threads",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app.add_option_function<int>(n, [&o](const int& v) { o.threads = v; }, h)->check(integer_in(0, config::shared_ranges::kThreadsMax));
     },
     [](const config::Overrides& o) { return o.threads ? text(static_cast<long long>(*o.threads)) : std::string(); }},
    {OverrideFlag::duration, "--duration", "SECONDS", "seconds of spin-up instead of dem.run.duration",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app.add_option_function<double>(n, [&o](const double& v) { o.duration = v; }, h)
           ->check(number_in(config::shared_ranges::duration(), "s"));
     },
     [](const config::Overrides& o) { return o.duration ? text(*o.duration) : std::string(); }},
    {OverrideFlag::speed_rpm, "--speed-rpm", "RPM", "the receiver's speed (or, without one, the DEM drum's), rpm",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app.add_option_function<double>(n, [&o](const double& v) { o.speed_rpm = v; }, h)
           ->check(number_in(config::shared_ranges::speed_rpm(), "rpm"));
     },
     [](const config::Overrides& o) { return o.speed_rpm ? text(*o.speed_rpm) : std::string(); }},
    {OverrideFlag::mass_flow, "--mass-flow", "KG_S", "the receiver's mass flow (or, without one, the DEM feeder's), kg/s",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app.add_option_function<double>(n, [&o](const double& v) { o.mass_flow = v; }, h)
           ->check(number_in(config::shared_ranges::mass_flow(), "kg/s"));
     },
     [](const config::Overrides& o) { return o.mass_flow ? text(*o.mass_flow) : std::string(); }},
    {OverrideFlag::seed, "--seed", "N", "the DEM's random seed instead of dem.seed (a replica of the same case)",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app.add_option_function<long long>(n, [&o](const long long& v) { o.seed = static_cast<std::uint64_t>(v); }, h)
           ->check(integer_in(0, config::shared_ranges::kSeedMax));
     },
     [](const config::Overrides& o) { return o.seed ? text(static_cast<long long>(*o.seed)) : std::string(); }},
    {OverrideFlag::wall_rolling_model, "--wall-rolling-model", "relative|liggghts",
     "contacts.wall_rolling_model instead of the case's (liggghts: LIGGGHTS' form)",
     [](CommandLine& app, config::Overrides& o, const char* n, const char* h) {
       return app
           .add_option_function<std::string>(
               n,
               [&o](const std::string& v) {
                 o.wall_rolling = v == "relative" ? dem::WallRolling::relative : dem::WallRolling::liggghts;
               },
               h)
           ->check(CLI::IsMember({"relative", "liggghts"}));
     },
     [](const config::Overrides& o) { return o.wall_rolling ? std::string(text(*o.wall_rolling)) : std::string(); }},
};
}  // namespace

void add_override_flags(CommandLine& app, config::Overrides& o, std::initializer_list<OverrideFlag> which) {
  for (const OverrideFlag w : which)
    for (const Flag& f : kFlags)
      if (f.which == w) f.add(app, o, f.name, f.help)->option_text(f.value);
}

Args override_args(const config::Overrides& o) {
  Args a;
  for (const Flag& f : kFlags) {
    const std::string v = f.given(o);
    if (!v.empty()) a.insert(a.end(), {f.name, v});
  }
  return a;
}

std::vector<std::string> override_flag_names() {
  std::vector<std::string> names;
  for (const Flag& f : kFlags) names.push_back(f.name);
  return names;
}

std::string flags_text(const config::Overrides& o) {
  std::string s;
  for (const std::string& a : override_args(o)) s += (s.empty() ? "" : " ") + a;
  return s;
}

config::CaseFile checked_overrides(const config::CaseFile& cf, const config::Overrides& o) {
  try {
    return config::with_overrides(cf, o);
  } catch (const config::ConfigError& e) {
    throw UsageError("with " + flags_text(o) + ": " + e.what());
  }
}

config::DemCase checked_dem(const config::CaseFile& cf, const config::Overrides& o) {
  const config::ReceiverCase* receiver = cf.receiver ? &*cf.receiver : nullptr;
  config::DemCase dc;
  try {
    dc = config::effective_dem(*cf.dem, receiver, o);
  } catch (const std::invalid_argument& e) {
    throw UsageError("with " + flags_text(o) + ": " + e.what());
  }
  if (const auto p = config::dem_run_problem(dc, receiver && receiver->dem_diameter_d > 0.0))
    throw UsageError("with " + flags_text(o) + ": " + p->key + ": " + p->message);
  return dc;
}

}  // namespace centrec::cli
