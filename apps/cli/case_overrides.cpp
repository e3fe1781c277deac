#include "cli/case_overrides.hpp"

#include <sstream>
#include <stdexcept>

#include "cli/command_line.hpp"

namespace centrec::cli {

std::string flags_text(const config::Overrides& o) {
  std::ostringstream s;
  s.precision(10);
  auto flag = [&](const char* name, auto value) { s << (s.tellp() > 0 ? " " : "") << name << ' ' << value; };
  if (o.threads) flag("--threads", *o.threads);
  if (o.duration) flag("--duration", *o.duration);
  if (o.speed_rpm) flag("--speed-rpm", *o.speed_rpm);
  if (o.mass_flow) flag("--mass-flow", *o.mass_flow);
  if (o.seed) flag("--seed", *o.seed);
  return s.str();
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
