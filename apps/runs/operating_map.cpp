#include "operating_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/film_field_h5.hpp"
#include "io/summary_json.hpp"

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

OperatingMap read_operating_map(const std::string& sweep_dir) {
  const std::string path = sweep_dir + "/sweep.json";
  const nlohmann::json j = io::read_json_file(path);
  OperatingMap m;
  m.dir = sweep_dir;
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
    p.speed_rpm = row.at("speed_rpm").get<double>();
    p.mass_flow = row.at("mass_flow_kg_s").get<double>();
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

std::vector<coupling::SurrogateSample> surrogate_samples(const OperatingMap& m, double receiver_diameter) {
  std::vector<coupling::SurrogateSample> out;
  for (const MapPoint& p : m.points) {
    if (!p.usable) continue;
    coupling::SurrogateSample s;
    s.speed_rpm = p.speed_rpm;
    s.mass_flow = p.mass_flow;
    s.film = io::read_film_field(io::H5File::open_read(p.dir + "/film.h5"));
    s.film.drum_diameter = receiver_diameter;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace centrec::runs
