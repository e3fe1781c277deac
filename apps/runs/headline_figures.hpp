#pragma once
// The headline figures of a coupled run (docs/outputs.md "Sweep"): one list says where each
// sits in summary.json, its column in sweep.csv and its unit, so that the replicas' spread,
// the sweep's table and its JSON rows all report the same figures under the same names.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace centrec::runs {

struct HeadlineFigure {
  std::string pointer;  // JSON pointer into a run's summary.json
  std::string column;   // its sweep.csv column and sweep.json key (<column>_std with --replicas)
  std::string unit;     // "-" for a ratio
};

const std::vector<HeadlineFigure>& headline_figures();

// The inputs that define a run's point (summary.json "point": speed, mass flow, inlet
// temperature, mean flux on the film, DEM seed and step; null where the run has none, e.g.
// the DEM's in a thermal-only run), under their sweep.csv columns.
const std::vector<HeadlineFigure>& point_inputs();

// The figure's number in a summary.json, or false where the summary has none there (a
// thermal-only run has no DEM figures).
bool headline_value(const nlohmann::json& summary, const HeadlineFigure& f, double& out);

}  // namespace centrec::runs
