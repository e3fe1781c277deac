#include "config/case_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "config/case_checks.hpp"

namespace centrec::config {

namespace {

// "dem.run.threads" -> {"dem", "run", "threads"}.
std::vector<std::string> key_path_parts(const std::string& dotted) {
  std::vector<std::string> parts;
  std::stringstream path(dotted);
  for (std::string part; std::getline(path, part, '.');) parts.push_back(part);
  return parts;
}

CaseFile read_case(MapReader root, const std::string& path) {
  CaseFile c;
  c.path = path;
  // A misspelt section is reported as such before the sections are read.
  root.known_keys({"title", "description", "dem", "receiver", "film", "thermal", "sweep"});
  c.title = root.string("title", "", "a one-line name of the case, echoed into the outputs");
  root.string("description", "", "free text about the case");
  if (root.has("dem"))
    c.dem = read_dem_case(root.child("dem", "the DEM of the drum or slice (`centrec dem`, the DEM stage of `run`)"));
  if (root.has("receiver")) {
    if (!c.dem) root.fail("receiver", "a receiver is simulated through a scaled-down `dem:` section; add one");
    c.receiver = read_receiver(root.child("receiver", "the full-size receiver a coupled run scales the film to"),
                               root.child("dem"));
  }
  if (c.dem) {
    // What the DEM commands check before they start, on the drum they would simulate.
    DemCase run;
    try {
      run = effective_dem(*c.dem, c.receiver ? &*c.receiver : nullptr, {});
    } catch (const std::invalid_argument& e) {
      root.fail("receiver", e.what());
    }
    if (const auto p = dem_run_problem(run, c.receiver && c.receiver->dem_diameter_d > 0.0))
      root.fail_path(p->key, p->message);
  }
  if (root.has("film") || root.has("thermal")) {
    ThermalCase t;
    t.path = path;
    t.title = c.title;
    // In a coupled case (with `dem:`) the film comes from the DEM, so `film:` is optional.
    read_thermal_sections(root, case_directory(path), t, c.dem.has_value());
    c.thermal = std::move(t);
  }
  if (c.dem && c.thermal && c.thermal->film_source.from_dem())
    if (const auto p = coupled_run_problem(*c.dem, *c.thermal, c.receiver ? &*c.receiver : nullptr))
      root.fail_path(p->key, p->message);
  if (root.has("sweep") && !c.dem)
    root.fail("sweep", "grids speed x mass flow through the DEM; this case has no dem: section to run them on");
  if (root.has("sweep"))
    c.sweep = read_sweep(root.child("sweep", "the operating map of `centrec sweep`: speed x mass flow"));
  if (c.sweep && c.dem)
    if (const auto p = sweep_problem(*c.dem, c.receiver ? &*c.receiver : nullptr, *c.sweep))
      root.fail_path(p->key, p->message);
  root.finish();
  c.resolved_yaml = root.resolved_text();
  return c;
}

}  // namespace

CaseFile read_case_file(const std::string& path) {
  MapReader root = MapReader::from_file(path);
  CaseFile c = read_case(root, path);
  // A settled start's source run must be there when the case is read from its file (a
  // checkpoint's resolved configuration is read again after its source may have gone: a
  // resume does not need it).
  if (c.dem && !c.dem->initial_film_from_run.empty()) {
    const std::string dir = settled_start_dir(path, *c.dem);
    if (!std::filesystem::is_regular_file(dir + "/checkpoint.h5"))
      root.fail_path("dem.initial_film.from_run", "no run to start from: " + dir +
                                                      "/checkpoint.h5 does not exist (run that case first, into "
                                                      "that folder)");
  }
  return c;
}

CaseFile read_case_text(const std::string& text, const std::string& path) {
  return read_case(MapReader::from_string(text, path + " (resolved configuration)"), path);
}

CaseFile read_case_recording(const std::string& text, const std::string& path, std::vector<KeyRecord>& keys) {
  MapReader root = MapReader::from_string(text, path);
  root.record_keys(&keys);
  return read_case(root, path);
}

std::string shortest_text(double v) {
  char b[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

CaseFile with_overrides(const CaseFile& cf, const Overrides& o) {
  if (o.keys.empty() && !o.any_operating_point()) return cf;
  YAML::Node root = YAML::Load(cf.resolved_yaml);
  // The operating point is written where it applies (effective_dem applies it again, the
  // same values), so the resolved case records the point that ran: the receiver's, or
  // without one the DEM drum's speed and its feed or slice target.
  if (o.any_operating_point() && cf.receiver) {
    if (o.speed_rpm) root["receiver"]["speed_rpm"] = shortest_text(*o.speed_rpm);
    if (o.mass_flow) root["receiver"]["mass_flow"] = shortest_text(*o.mass_flow);
  } else if (o.any_operating_point() && cf.dem) {
    if (o.speed_rpm) root["dem"]["drum"]["speed_rpm"] = shortest_text(*o.speed_rpm);
    if (o.mass_flow)
      root["dem"][cf.dem->scene.slice.enabled ? "slice" : "feeder"]
          [cf.dem->scene.slice.enabled ? "target_mass_flow" : "mass_flow"] = shortest_text(*o.mass_flow);
  }
  for (const auto& [key, value] : o.keys) {
    const std::vector<std::string> parts = key_path_parts(key);
    if (parts.size() < 2 || std::find(parts.begin(), parts.end(), "") != parts.end())
      throw ConfigError(key + ": not a key path of a case (section.key, e.g. dem.run.threads)");
    if (!root[parts[0]].IsDefined())
      throw ConfigError(key + ": the case " + cf.path + " has no `" + parts[0] + ":` section to set it in");
    YAML::Node node = root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (node[parts[i]].IsDefined() && !node[parts[i]].IsMap())
        throw ConfigError(key + ": " + parts[i] + " is not a section of keys in " + cf.path);
      node.reset(node[parts[i]]);
    }
    node[parts.back()] = value;
  }
  YAML::Emitter e;
  e << root;
  return read_case_text(e.c_str(), cf.path);
}

std::string resolved_value(const CaseFile& cf, const std::string& dotted) {
  YAML::Node node = YAML::Load(cf.resolved_yaml);
  for (const std::string& part : key_path_parts(dotted)) {
    if (!node.IsMap() || !node[part].IsDefined()) return "";
    node.reset(node[part]);
  }
  return node.IsScalar() ? node.Scalar() : "";
}

}  // namespace centrec::config
