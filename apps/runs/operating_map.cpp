#include "operating_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "config/case_file.hpp"
#include "io/film_field_h5.hpp"
#include "io/summary_json.hpp"
#include "runs/dem_inputs.hpp"

namespace centrec::runs {

namespace {

// The last line a failed run wrote about itself ("centrec run: ..."), or a fallback.
std::string refusal_of(const std::string& dir) {
  std::ifstream in(dir + "/run.log");
  std::string line, last;
  while (std::getline(in, line))
    if (line.rfind("centrec", 0) == 0) last = line;
  return last.empty() ? "the run failed (see " + dir + "/run.log)" : last;
}

std::size_t index_of(const std::vector<double>& v, double x) {
  return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
}

// The cell [i, i+1] of `grid` holding x (false outside the grid).
bool cell_of(const std::vector<double>& grid, double x, std::size_t& i) {
  if (grid.size() < 2 || x < grid.front() || x > grid.back()) return false;
  i = std::min(index_of(grid, x), grid.size() - 1);
  if (i > 0 && grid[i] > x) --i;
  if (i == grid.size() - 1) --i;
  return true;
}

// The cells holding x: on an interior node of the grid both neighbours (the window is closed:
// a node on its edge is inside it), else the one cell (none outside the grid).
std::vector<std::size_t> cells_of(const std::vector<double>& grid, double x) {
  std::size_t i = 0;
  if (!cell_of(grid, x, i)) return {};
  if (i > 0 && grid[i] == x) return {i - 1, i};
  return {i};
}

}  // namespace

const MapPoint* OperatingMap::at(std::size_t i, std::size_t j) const {
  if (i >= speeds.size() || j >= flows.size()) return nullptr;
  for (const MapPoint& p : points)
    if (p.speed_rpm == speeds[i] && p.mass_flow == flows[j]) return &p;
  return nullptr;
}

namespace {
bool cell_usable(const OperatingMap& m, std::size_t i, std::size_t j) {
  if (i + 1 >= m.speeds.size() || j + 1 >= m.flows.size()) return false;
  for (std::size_t a : {i, i + 1})
    for (std::size_t b : {j, j + 1}) {
      const MapPoint* p = m.at(a, b);
      if (!p || !p->usable) return false;
    }
  return true;
}
}  // namespace

namespace {
// A usable cell holding (speed, mass flow), if any.
bool usable_cell_at(const OperatingMap& m, double speed_rpm, double mass_flow, std::size_t& i, std::size_t& j) {
  for (std::size_t a : cells_of(m.speeds, speed_rpm))
    for (std::size_t b : cells_of(m.flows, mass_flow))
      if (cell_usable(m, a, b)) {
        i = a, j = b;
        return true;
      }
  return false;
}
}  // namespace

bool OperatingMap::inside(double speed_rpm, double mass_flow) const {
  std::size_t i = 0, j = 0;
  return usable_cell_at(*this, speed_rpm, mass_flow, i, j);
}

WindowMargin OperatingMap::margin(double speed_rpm, double mass_flow) const {
  WindowMargin w;
  std::size_t i = 0, j = 0;
  if (!usable_cell_at(*this, speed_rpm, mass_flow, i, j)) return w;
  std::size_t lo = i, hi = i;
  while (lo > 0 && cell_usable(*this, lo - 1, j)) --lo;
  while (cell_usable(*this, hi + 1, j)) ++hi;
  w.speed_below = speed_rpm - speeds[lo];
  w.speed_above = speeds[hi + 1] - speed_rpm;
  lo = hi = j;
  while (lo > 0 && cell_usable(*this, i, lo - 1)) --lo;
  while (cell_usable(*this, i, hi + 1)) ++hi;
  w.flow_below = mass_flow - flows[lo];
  w.flow_above = flows[hi + 1] - mass_flow;
  return w;
}

std::pair<double, double> OperatingMap::flow_span(double speed_rpm) const {
  std::pair<double, double> best{0.0, 0.0};
  for (std::size_t i : cells_of(speeds, speed_rpm))
    for (std::size_t j = 0; j + 1 < flows.size();) {
      if (!cell_usable(*this, i, j)) {
        ++j;
        continue;
      }
      std::size_t k = j;
      while (cell_usable(*this, i, k + 1)) ++k;
      if (flows[k + 1] - flows[j] > best.second - best.first) best = {flows[j], flows[k + 1]};
      j = k + 1;
    }
  return best;
}

OperatingMap read_operating_map(const std::string& sweep_dir, const MapScaling& scaling) {
  const std::string path = sweep_dir + "/sweep.json";
  const nlohmann::json j = io::read_json_file(path);
  OperatingMap m;
  m.dir = sweep_dir;
  m.scaling = scaling;
  m.case_path = j.value("case", "");
  bool speed = false, flow = false;
  for (const auto& a : j.at("axes")) {
    const std::string c = a.value("column", "");
    if (c == "speed_rpm") speed = true;
    else if (c == "mass_flow_kg_s") flow = true;
    // Each point's start, near its own state, and how long its spin-up may take to settle:
    // neither is in a steady film (a point that did not settle is not usable anyway).
    else if (c.rfind("dem.initial_film.", 0) == 0 || c == "dem.run.duration" || c == "dem.run.max_extension")
      continue;
    else
      throw std::runtime_error(path + ": the sweep also varies " + c +
                               "; an operating map varies only speed_rpm and mass_flow_kg_s (the film depends on "
                               "nothing else), each point's start (dem.initial_film.*) and its spin-up "
                               "(dem.run.duration, dem.run.max_extension)");
  }
  if (!speed || !flow)
    throw std::runtime_error(path + ": an operating map is a sweep over speed_rpm and mass_flow_kg_s (`centrec "
                                    "sweep CASE` with the case's sweep: section, or --grid on both)");
  for (const auto& row : j.at("points")) {
    MapPoint p;
    p.speed_rpm = row.at("speed_rpm").get<double>() * scaling.speed;
    p.mass_flow = row.at("mass_flow_kg_s").get<double>() * scaling.flow;
    // The point's folder under the sweep's, wherever the sweep ran from.
    p.dir = sweep_dir + "/" + std::filesystem::path(row.at("dir").get<std::string>()).filename().string();
    if (row.value("status", 1) != 0) {
      p.state = refusal_of(p.dir);
    } else {
      p.T_out = row.value("T_out_K", 0.0);
      p.efficiency = row.value("efficiency", 0.0);
      const double closure = row.value("flow_closure", 0.0);
      const bool steady = row.value("dem_flow_steady", false);
      char buf[96];
      std::snprintf(buf, sizeof buf, "closure %.1f %%", 100.0 * closure);
      p.usable = steady && std::abs(closure - 1.0) <= kMapClosureTolerance;
      p.state = std::string(steady ? "steady, " : "NOT steady (" + row.value("dem_flow", std::string()) + "), ") +
                buf + (std::abs(closure - 1.0) <= kMapClosureTolerance ? "" : " (outside 3 %)");
    }
    m.points.push_back(p);
    m.speeds.push_back(p.speed_rpm);
    m.flows.push_back(p.mass_flow);
  }
  for (auto* v : {&m.speeds, &m.flows}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  return m;
}

namespace {

// A point's start and spin-up vary over a map (read_operating_map's axes): not the film's.
bool varies_per_point(const std::string& key) {
  return key.rfind("dem.initial_film.", 0) == 0 || key == "dem.run.duration" || key == "dem.run.max_extension";
}

// The map's own resolved case: its first finished point's, else the case file it names.
std::string map_resolved_config(const std::string& sweep_dir) {
  const nlohmann::json j = io::read_json_file(sweep_dir + "/sweep.json");
  for (const auto& row : j.at("points")) {
    const std::string dir =
        sweep_dir + "/" + std::filesystem::path(row.at("dir").get<std::string>()).filename().string();
    if (row.value("status", 1) == 0 && std::filesystem::exists(dir + "/summary.json")) {
      const nlohmann::json s = io::read_json_file(dir + "/summary.json");
      if (s.contains("resolved_config") && s["resolved_config"].is_string()) return s["resolved_config"];
    }
  }
  const std::string case_path = j.value("case", "");
  if (case_path.empty() || !std::filesystem::exists(case_path))
    throw std::runtime_error(sweep_dir + ": no finished point with a summary.json and no readable case file (\"" +
                             case_path + "\" in sweep.json): operate cannot tell which receiver the map is of");
  return config::read_case_file(case_path).resolved_yaml;
}

}  // namespace

MapScaling map_scaling_for(const std::string& sweep_dir, const std::string& case_resolved_yaml) {
  auto mine = dem_input_values(case_resolved_yaml, {"dem", "receiver"});
  auto theirs = dem_input_values(map_resolved_config(sweep_dir), {"dem", "receiver"});
  auto number = [](const std::map<std::string, std::string>& m, const std::string& k) {
    const auto it = m.find(k);
    return it == m.end() ? 0.0 : std::strtod(it->second.c_str(), nullptr);
  };
  const double D = number(mine, "receiver.diameter"), L = number(mine, "receiver.length");
  const double D_map = number(theirs, "receiver.diameter"), L_map = number(theirs, "receiver.length");
  std::string differ;
  if (!(D > 0 && L > 0 && D_map > 0 && L_map > 0))
    differ += "\n  receiver.diameter / length: both cases need a receiver";
  else if (std::abs(L / D - L_map / D_map) > 1e-9 * (L / D))
    differ += "\n  receiver L / D: " + std::to_string(L / D) + " here, " + std::to_string(L_map / D_map) + " in the map";
  // The operating point is the map's axes; the size is the scaling; every other key is the film's.
  auto scaled_or_axis = [](const std::string& k) {
    return k == "receiver.diameter" || k == "receiver.length" || k == "receiver.speed_rpm" ||
           k == "receiver.mass_flow" || varies_per_point(k);
  };
  std::map<std::string, std::string> keys;
  for (const auto* m : {&mine, &theirs})
    for (const auto& kv : *m) keys[kv.first];
  for (const auto& kv : keys) {
    const std::string& k = kv.first;
    if (scaled_or_axis(k)) continue;
    const auto a = mine.find(k), b = theirs.find(k);
    const std::string va = a == mine.end() ? "(absent)" : a->second, vb = b == theirs.end() ? "(absent)" : b->second;
    if (va != vb) differ += "\n  " + k + ": " + va + " here, " + vb + " in the map";
  }
  if (number(mine, "receiver.dem_diameter_d") <= 0.0)
    differ += "\n  receiver.dem_diameter_d: the receiver does not derive its DEM drum (eqs 1-3), so no map scales to it";
  if (!differ.empty())
    throw std::runtime_error("the map in " + sweep_dir +
                             " is not of this receiver's scaled film (eqs 1-3 derive another DEM):" + differ);
  MapScaling sc;
  sc.speed = std::sqrt(D_map / D);
  sc.flow = D / D_map;
  sc.length = L / L_map;
  if (D == D_map && L == L_map) sc = MapScaling{};
  return sc;
}

std::vector<coupling::SurrogateSample> surrogate_samples(const OperatingMap& m, double receiver_diameter) {
  std::vector<coupling::SurrogateSample> out;
  for (const MapPoint& p : m.points) {
    if (!p.usable) continue;
    coupling::SurrogateSample s;
    s.speed_rpm = p.speed_rpm;
    s.mass_flow = p.mass_flow;
    s.film = io::read_film_field(io::H5File::open_read(p.dir + "/film.h5"));
    s.film.drum_diameter = receiver_diameter;
    for (double& z : s.film.z) z *= m.scaling.length;
    s.film.length *= m.scaling.length;
    s.film.omega *= m.scaling.speed;
    s.film.mdot *= m.scaling.flow;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace centrec::runs
