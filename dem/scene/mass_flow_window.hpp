#pragma once
// Inlet and outlet mass flow of a drum over its last stretch of time, from the cumulative
// mass-flow log: the one definition behind the run report, summary.json and the flow the
// coupled run hands to the thermal film.
#include <vector>

#include "dem/scene/centrec_scene.hpp"

namespace centrec::dem::scene {

struct WindowFlows {
  double fed = 0.0, out = 0.0;  // kg/s
};

// Mean flows between the last sample and the latest sample at least `window` seconds
// before it (the first sample if the log is shorter); zeros for a log without two samples.
WindowFlows window_flows(const std::vector<MassFlowSample>& log, double window);

}  // namespace centrec::dem::scene
