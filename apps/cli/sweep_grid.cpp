#include "cli/sweep_grid.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "config/shared_ranges.hpp"

namespace centrec::cli {

namespace {

bool is_speed(const std::string& key) { return key == "speed_rpm"; }
bool is_flow(const std::string& key) { return key == "mass_flow"; }

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string p; std::getline(in, p, sep);) parts.push_back(trimmed(p));
  if (!s.empty() && s.back() == sep) parts.push_back("");
  return parts;
}

// A value that reads fully as a number, in the shortest text that reads back as it (so
// 2e5, 200000 and 2.0e5 name one folder); any other value as given.
std::string canonical(const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  return !v.empty() && end && *end == '\0' ? shortest_text(x) : v;
}

// The operating point's value, checked against the range the receiver's keys share.
double point_value(const SweepAxis& axis, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  const config::Range range = is_speed(axis.key) ? config::shared_ranges::speed_rpm() : config::shared_ranges::mass_flow();
  if (v.empty() || !end || *end != '\0' || !range.contains(x))
    throw UsageError("sweep " + axis.key + ": '" + v + "' is not a number in " + range.describe() +
                     (is_speed(axis.key) ? " rpm" : " kg/s"));
  return x;
}

// A folder name's part for an axis: the key's last word (the operating point as rpm / mdot,
// as the case's own sweep names its folders), or the whole key where two axes share it.
std::string short_name(const std::vector<SweepAxis>& axes, std::size_t i) {
  if (is_speed(axes[i].key)) return "rpm";
  if (is_flow(axes[i].key)) return "mdot";
  auto last = [](const std::string& k) { return k.substr(k.rfind('.') + 1); };
  for (std::size_t j = 0; j < axes.size(); ++j)
    if (j != i && last(axes[j].key) == last(axes[i].key)) return axes[i].key;
  return last(axes[i].key);
}

std::string folder_safe(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '+' && c != '-' && c != '_') c = '_';
  return out;
}

SweepPoint make_point(const std::vector<SweepAxis>& axes, const std::vector<std::string>& values,
                      const config::Overrides& given) {
  SweepPoint p;
  p.values = values;
  p.overrides = given;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const SweepAxis& a = axes[i];
    if (is_speed(a.key)) {
      p.overrides.speed_rpm = point_value(a, values[i]);
    } else if (is_flow(a.key)) {
      p.overrides.mass_flow = point_value(a, values[i]);
    } else {
      p.overrides.keys[a.key] = values[i];
    }
    p.name += (i ? "_" : "") + folder_safe(short_name(axes, i) + canonical(values[i]));
  }
  return p;
}

// Folder names unique by construction: a repeated point is refused; two different points
// whose names coincide once made safe for a folder are numbered instead.
SweepGrid finished(std::vector<SweepAxis> axes, std::vector<SweepPoint> points, const std::string& where) {
  std::map<std::vector<std::string>, std::size_t> seen;
  std::set<std::string> names;
  bool clash = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::vector<std::string> canon;
    for (const std::string& v : points[k].values) canon.push_back(canonical(v));
    const auto [at, fresh] = seen.emplace(canon, k);
    if (!fresh) throw UsageError(where + ": the point " + points[k].name + " is given twice (points " +
                                 std::to_string(at->second + 1) + " and " + std::to_string(k + 1) + ")");
    clash = clash || !names.insert(points[k].name).second;
  }
  if (clash)
    for (std::size_t k = 0; k < points.size(); ++k) points[k].name = "point" + std::to_string(k + 1);
  return {std::move(axes), std::move(points)};
}

void refuse_repeated_keys(const std::vector<SweepAxis>& axes, const config::Overrides& given, const std::string& where) {
  std::set<std::string> keys;
  for (const SweepAxis& a : axes) {
    if (!keys.insert(a.key).second) throw UsageError(where + ": the key " + a.key + " is swept twice");
    const bool by_flag = (is_speed(a.key) && given.speed_rpm) || (is_flow(a.key) && given.mass_flow) || given.sets(a.key);
    if (by_flag) throw UsageError(where + ": " + a.key + " is both swept and set for every point");
  }
}

}  // namespace

SweepAxis sweep_axis(const std::string& key) {
  return {key, is_speed(key) ? "speed_rpm" : is_flow(key) ? "mass_flow_kg_s" : key};
}

std::pair<SweepAxis, std::vector<std::string>> parse_grid_flag(const std::string& flag) {
  const std::size_t eq = flag.find('=');
  const std::string key = trimmed(flag.substr(0, eq));
  if (eq == std::string::npos || key.empty())
    throw UsageError("--grid '" + flag + "' is not KEY=v1,v2,... (e.g. thermal.flux.q_film=1.5e5,2e5)");
  const std::vector<std::string> values = split(flag.substr(eq + 1), ',');
  for (const std::string& v : values)
    if (v.empty()) throw UsageError("--grid '" + flag + "': an empty value in the list");
  return {sweep_axis(key), values};
}

SweepGrid cartesian_grid(const std::vector<std::pair<SweepAxis, std::vector<std::string>>>& axes,
                         const config::Overrides& given) {
  std::vector<SweepAxis> a;
  for (const auto& [axis, values] : axes) a.push_back(axis);
  refuse_repeated_keys(a, given, "--grid");
  std::vector<std::vector<std::string>> rows{{}};
  for (const auto& [axis, values] : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& row : rows)
      for (const std::string& v : values) {
        next.push_back(row);
        next.back().push_back(v);
      }
    rows = std::move(next);
  }
  std::vector<SweepPoint> points;
  for (const auto& row : rows) points.push_back(make_point(a, row, given));
  return finished(std::move(a), std::move(points), "--grid");
}

SweepGrid points_from_csv(const std::string& path, const config::Overrides& given) {
  std::ifstream in(path);
  if (!in) throw UsageError("--points " + path + ": cannot read the file");
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = split(t, ',');
    const std::string at = path + ":" + std::to_string(n);
    if (axes.empty()) {
      for (const std::string& key : cells) {
        if (key.empty()) throw UsageError(at + ": an empty key in the header");
        axes.push_back(sweep_axis(key));
      }
      refuse_repeated_keys(axes, given, at);
      continue;
    }
    if (cells.size() != axes.size())
      throw UsageError(at + ": " + std::to_string(cells.size()) + " values for the header's " +
                       std::to_string(axes.size()) + " keys");
    for (const std::string& v : cells)
      if (v.empty()) throw UsageError(at + ": an empty value");
    try {
      points.push_back(make_point(axes, cells, given));
    } catch (const UsageError& e) {
      throw UsageError(at + ": " + e.what());
    }
  }
  if (points.empty()) throw UsageError("--points " + path + ": no point (a header of keys, then a row per point)");
  return finished(std::move(axes), std::move(points), "--points " + path);
}

void check_sweep_points(const config::CaseFile& cf, const SweepGrid& grid) {
  for (const SweepPoint& p : grid.points) {
    try {
      const config::CaseFile point = checked_overrides(cf, p.overrides, "sweep");
      if (point.dem) checked_dem(point, p.overrides, "sweep");
    } catch (const config::ConfigError& e) {
      throw UsageError("the sweep point " + p.name + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw UsageError("the sweep point " + p.name + ": " + e.what());
    }
  }
}

}  // namespace centrec::cli
