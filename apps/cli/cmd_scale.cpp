// `centrec scale`: the scaled-down receiver that carries the same film (paper eqs 1-3).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_receiver.hpp"
#include "config/strict_yaml.hpp"
#include "coupling/scaling_laws.hpp"
#include "io/atomic_write.hpp"

namespace centrec::cli {

namespace {

using coupling::ReceiverOperatingPoint;
using config::ConfigError;

const char* kUsage =
    "usage: centrec scale [--input FILE] --diameter D --length L --speed-rpm N --mdot M\n"
    "                     (--target-diameter D | --target-d-over-d X) [options]\n"
    "\n"
    "Scales an actual receiver to another size by the paper's eqs (1)-(3): keeps\n"
    "omega^2 R (eq 1), mdot / R (eq 2) and L / R (eq 3); film thickness in d and\n"
    "velocities carry over. Prints both operating points with the inlet speed omega R,\n"
    "omega^2 R / g and, if a holdup is given, the particle count.\n"
    "\n"
    "actual receiver (SI units; from flags, or from the receiver: section of --input):\n"
    "  --diameter D            cavity diameter, m                 (receiver: diameter)\n"
    "  --length L              cavity length, m                   (receiver: length)\n"
    "  --speed-rpm N           rotational speed, rpm              (receiver: speed_rpm)\n"
    "  --mdot M                particle mass flow, kg/s           (receiver: mass_flow)\n"
    "  --particle-diameter d   m, default 1.2e-3 (paper Table 1)  (receiver: particle_diameter)\n"
    "  --input FILE            YAML file with a receiver: section holding the keys above\n"
    "                          (other top-level sections are ignored, so a case file\n"
    "                          works; a key given both there and as a flag is an error)\n"
    "target (exactly one):\n"
    "  --target-diameter D     target cavity diameter, m\n"
    "  --target-d-over-d X     target D / d (same particles)\n"
    "holdup, for the particle count (at most one):\n"
    "  --holdup-particles N    particles held in the actual receiver\n"
    "  --holdup-kg M           mass held in the actual receiver (uses --density)\n"
    "  --film-thickness-d T    film thickness in d (uses --solid-fraction)\n"
    "other:\n"
    "  --density RHO           particle density, kg/m^3, default 3560 (paper Table 1)\n"
    "  --solid-fraction F      film solid fraction, default 0.5 (paper section 4)\n"
    "  --gravity G             m/s^2, default 9.81\n"
    "  --yaml FILE             also write the scaled receiver as a YAML receiver: section\n"
    "                          (readable again by --input: scaling twice = scaling once)\n"
    "\n"
    "example: centrec scale --diameter 1.5 --length 2.1 --speed-rpm 45 --mdot 2.0 \\\n"
    "             --target-d-over-d 33\n";

// The receiver: section's key for each actual-receiver flag.
const std::map<std::string, std::string> kReceiverKeys = {{"--diameter", "diameter"},
                                                          {"--length", "length"},
                                                          {"--speed-rpm", "speed_rpm"},
                                                          {"--mdot", "mass_flow"},
                                                          {"--particle-diameter", "particle_diameter"}};
const char* kOtherFlags[] = {"--target-diameter", "--target-d-over-d", "--holdup-particles", "--holdup-kg",
                             "--film-thickness-d", "--density", "--solid-fraction", "--gravity"};

struct Request {
  std::map<std::string, double> value;  // by flag name
  std::string input, yaml_out;
  double get(const std::string& flag, double fallback) const {
    const auto it = value.find(flag);
    return it == value.end() ? fallback : it->second;
  }
  bool has(const std::string& flag) const { return value.count(flag) != 0; }
};

// The receiver: section's value for a key (absent keys are empty).
std::optional<double> section_value(const config::ReceiverSection& s, const std::string& key) {
  if (key == "diameter") return s.diameter;
  if (key == "length") return s.length;
  if (key == "speed_rpm") return s.speed_rpm;
  if (key == "mass_flow") return s.mass_flow;
  if (key == "particle_diameter") return s.particle_diameter;
  return std::nullopt;
}

Request parse(const Args& args) {
  Request r;
  CommandLine app("scale");
  for (const auto& [flag, key] : kReceiverKeys) app.add_option(flag, r.value[flag])->check(positive_number());
  for (const char* flag : kOtherFlags) app.add_option(flag, r.value[flag])->check(positive_number());
  app.add_option("--input", r.input);
  app.add_option("--yaml", r.yaml_out);
  app.read(args);
  for (auto it = r.value.begin(); it != r.value.end();) it = app.count(it->first) ? std::next(it) : r.value.erase(it);
  if (!r.input.empty()) {
    // The same reader as a case's receiver: (a case file works: its other sections are ignored).
    config::MapReader root = config::MapReader::from_file(r.input);
    if (!root.has("receiver")) throw ConfigError(r.input + ": no receiver: section");
    config::MapReader rec = root.child("receiver");
    const config::ReceiverSection section = config::read_receiver_section(rec, false);
    for (const auto& [flag, key] : kReceiverKeys) {
      const std::optional<double> v = section_value(section, key);
      if (!v) continue;
      if (r.has(flag)) rec.fail(key, "also given as " + flag + "; give it once");
      r.value[flag] = *v;
    }
  }
  for (const auto& [flag, key] : kReceiverKeys)
    if (flag != "--particle-diameter" && !r.has(flag))
      throw config::ConfigError("the actual receiver needs " + flag + " (or receiver: " + key + " in --input)");
  if (r.has("--target-diameter") == r.has("--target-d-over-d"))
    throw config::ConfigError("give exactly one of --target-diameter and --target-d-over-d");
  if (r.has("--holdup-particles") + r.has("--holdup-kg") + r.has("--film-thickness-d") > 1)
    throw config::ConfigError("give at most one of --holdup-particles, --holdup-kg, --film-thickness-d");
  if (r.get("--solid-fraction", 0.5) >= 1.0) throw config::ConfigError("--solid-fraction: must be below 1");
  return r;
}

// Particles held at each size, or nullopt if no holdup was given.
std::optional<double> particle_count(const Request& r, const ReceiverOperatingPoint& op,
                                     const ReceiverOperatingPoint& actual, double d) {
  if (r.has("--film-thickness-d"))
    return coupling::film_particle_count(op, r.get("--film-thickness-d", 0) * d, r.get("--solid-fraction", 0.5), d);
  double n_act = r.get("--holdup-particles", 0.0);
  if (r.has("--holdup-kg")) n_act = r.get("--holdup-kg", 0) / (r.get("--density", 3560.0) * M_PI * d * d * d / 6.0);
  if (n_act <= 0.0) return std::nullopt;
  return coupling::scale_particle_count(n_act, actual.diameter, op.diameter);
}

void print_row(const char* name, double a, double s, const char* fmt = "%-28s %14.6g %14.6g\n") {
  std::printf(fmt, name, a, s);
}

std::string yaml_snippet(const ReceiverOperatingPoint& a, const ReceiverOperatingPoint& s, double d,
                         std::optional<double> n, double g) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "# centrec scale (paper eqs 1-3) from D = %.10g m, L = %.10g m, %.10g rpm, %.10g kg/s\n"
                "receiver:\n"
                "  diameter: %.12g  # m\n"
                "  length: %.12g  # m\n"
                "  speed_rpm: %.12g\n"
                "  mass_flow: %.12g  # kg/s\n"
                "  particle_diameter: %.12g  # m\n"
                "# derived: D/d = %.6g, inlet speed omega R = %.6g m/s, omega^2 R / g = %.6g",
                a.diameter, a.length, coupling::rad_per_s_to_rpm(a.omega), a.mass_flow, s.diameter, s.length,
                coupling::rad_per_s_to_rpm(s.omega), s.mass_flow, d, s.diameter / d, coupling::inlet_speed(s),
                coupling::centrifugal_ratio(s, g));
  std::string text = buf;
  if (n) {
    std::snprintf(buf, sizeof buf, ", particles ~ %.4g", *n);
    text += buf;
  }
  return text + "\n";
}

}  // namespace

int cmd_scale(const Args& args) {
  if (wants_help(args) || args.empty()) {
    std::printf("%s", kUsage);
    return args.empty() ? 2 : 0;
  }
  const Request r = parse(args);
  const double d = r.get("--particle-diameter", 1.2e-3);
  const double g = r.get("--gravity", 9.81);
  ReceiverOperatingPoint act;
  act.diameter = r.get("--diameter", 0);
  act.length = r.get("--length", 0);
  act.omega = coupling::rpm_to_rad_per_s(r.get("--speed-rpm", 0));
  act.mass_flow = r.get("--mdot", 0);
  const double target = r.has("--target-diameter") ? r.get("--target-diameter", 0) : r.get("--target-d-over-d", 0) * d;
  // A drum of 20 particle diameters or less holds no film the DEM can run (its own bound,
  // config::dem_run_problem), far below the laws' validity (docs/validity_threshold.md).
  for (const auto& [what, D] : {std::pair<const char*, double>{"the actual receiver", act.diameter},
                                std::pair<const char*, double>{"the target drum", target}})
    if (!(D > 20.0 * d)) {
      char why[200];
      std::snprintf(why, sizeof why, "%s of D = %.4g m is D/d = %.4g: a drum must exceed 20 particle diameters", what,
                    D, D / d);
      throw config::ConfigError(std::string(why) + " (the DEM's bound; the scale-down laws hold from D/d 80)");
    }
  if (r.has("--film-thickness-d") && r.get("--film-thickness-d", 0) * d >= 0.5 * std::min(act.diameter, target))
    throw config::ConfigError("--film-thickness-d: the film would fill the drum");
  const ReceiverOperatingPoint sim = coupling::scale_to_diameter(act, target);
  const auto n_act = particle_count(r, act, act, d), n_sim = particle_count(r, sim, act, d);

  std::printf("centrec scale: paper eqs (1)-(3), keeping omega^2 R, mdot/R and L/R (d = %.4g m)\n\n", d);
  std::printf("%-28s %14s %14s\n", "", "actual", "scaled");
  print_row("cavity diameter D [m]", act.diameter, sim.diameter);
  print_row("D/d [-]", act.diameter / d, sim.diameter / d);
  print_row("cavity length L [m]", act.length, sim.length);
  print_row("rotational speed [rpm]", coupling::rad_per_s_to_rpm(act.omega), coupling::rad_per_s_to_rpm(sim.omega));
  print_row("omega [rad/s]", act.omega, sim.omega);
  print_row("mass flow [kg/s]", act.mass_flow, sim.mass_flow);
  print_row("inlet speed omega R [m/s]", coupling::inlet_speed(act), coupling::inlet_speed(sim));
  print_row("omega^2 R / g [-]", coupling::centrifugal_ratio(act, g), coupling::centrifugal_ratio(sim, g));
  if (n_act)
    print_row("particles in the film [-]", *n_act, *n_sim);
  else
    std::printf("%-28s %s\n", "particles in the film [-]", "(give --holdup-particles, --holdup-kg or --film-thickness-d)");
  std::printf("\nscale factor r_sim/r_act = %.6g; film thickness in d and velocities are unchanged;\n"
              "axial positions scale with L. Valid while D >> d (here D/d = %.4g).\n",
              sim.diameter / act.diameter, sim.diameter / d);
  const std::string small = coupling::scale_down_validity(sim.diameter, d);
  if (!small.empty())
    std::fprintf(stderr, "centrec scale: warning: %s; `centrec run` refuses it without --allow-small-drum\n",
                 small.c_str());
  if (!r.yaml_out.empty()) {
    io::write_text_atomically(r.yaml_out, yaml_snippet(act, sim, d, n_sim, g));
    std::printf("wrote %s\n", r.yaml_out.c_str());
  }
  return 0;
}

}  // namespace centrec::cli
