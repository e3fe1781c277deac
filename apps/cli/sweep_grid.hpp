#pragma once
// The points of `centrec sweep` (docs/outputs.md "Sweep"): axes of case keys, each with the
// values it takes, from `--grid KEY=v1,v2,...` (a Cartesian grid), from `--points FILE.csv`
// (one point a row, one key a column), or from the case's `sweep:` section (speed_rpm x
// mass_flow). A key is any case key as its dotted path (thermal.flux.q_film), or the
// operating point: `speed_rpm` (rpm) and `mass_flow` (kg/s), the receiver's, or the DEM
// drum's without one, as `centrec run --speed-rpm/--mass-flow` set them.
#include <string>
#include <vector>

#include "config/case_file.hpp"

namespace centrec::cli {

struct SweepAxis {
  std::string key;     // dotted case key, or "speed_rpm" / "mass_flow"
  std::string column;  // its sweep.csv column: the key, or speed_rpm / mass_flow_kg_s
};

struct SweepPoint {
  std::vector<std::string> values;  // one per axis, as given
  config::Overrides overrides;      // the sweep's --set plus this point's values
  std::string name;                 // its folder under the sweep's: unique in the sweep
};

struct SweepGrid {
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;
};

// An axis of the key, its column named.
SweepAxis sweep_axis(const std::string& key);

// "KEY=v1,v2,..." -> the axis and its values; a UsageError says what is wrong with the text.
std::pair<SweepAxis, std::vector<std::string>> parse_grid_flag(const std::string& flag);

// The Cartesian product of the axes' values (the first axis slowest), each point with
// `given` plus its values. Throws a UsageError for a key given twice (as two axes, or as an
// axis and by --set) or a repeated point.
SweepGrid cartesian_grid(const std::vector<std::pair<SweepAxis, std::vector<std::string>>>& axes,
                         const config::Overrides& given);

// The points of a CSV: a header of keys, then one row of values per point (blank lines and
// lines starting with # skipped). Throws a UsageError naming the file and line.
SweepGrid points_from_csv(const std::string& path, const config::Overrides& given);

// Every point's case is read with its values by the keys' own readers, and its DEM checked
// as `centrec run` would; the first refusal is thrown as a UsageError naming the point.
void check_sweep_points(const config::CaseFile& cf, const SweepGrid& grid);

}  // namespace centrec::cli
