#pragma once
// Flows of a DEM run over its last stretch of time, from the mass-flow log, and whether
// the run was steady there: the one definition behind the run report, summary.json, the
// run's extension until steady and the flow the coupled run hands to the thermal film
// (docs/centrec_scene.md "Steady state").
#include <string>
#include <vector>

#include "dem/scene/centrec_scene.hpp"

namespace centrec::dem::scene {

struct WindowFlows {
  double fed = 0.0, out = 0.0;   // kg/s, mean inlet and outlet flows (drum)
  double axial = 0.0;            // kg/s, mean axial flow of a slice (0 for a drum)
  double holdup_start = 0.0, holdup_end = 0.0;  // kg of free particles
  double seconds = 0.0;          // the window's actual length
};

// Mean flows between the last sample and the latest sample at least `window` seconds
// before it (the first sample if the log is shorter); zeros for a log without two samples.
WindowFlows window_flows(const std::vector<MassFlowSample>& log, double window);

// Steady flow over the window:
//  - a fed drum: the outlet within `tolerance` of the feed, |out / fed - 1| <= tolerance, in
//    the window and in the window before it (a filling wave's outflow crosses the feed: one
//    window astride the crossing averages to the feed);
//  - a slice with a flow controller: its axial flow within `tolerance` of the target;
//    a slice without one: the window's two halves agree within `tolerance`;
//  - and in both, the holdup drifted by at most `tolerance` of itself over the window
//    (a film still filling, draining or being corrected by the controller is not steady).
struct FlowSteadiness {
  double measured = 0.0;      // kg/s: the outlet (drum) or the axial flow (slice)
  double target = 0.0;        // kg/s: the feed (drum), the controller's target or the first half (slice)
  double flow_error = 0.0;    // measured / target - 1 (infinite without a target)
  double holdup_drift = 0.0;  // holdup_end / holdup_start - 1
  double previous_flow_error = 0.0, previous_holdup_drift = 0.0;  // a fed drum's window before (infinite: none)
  double window = 0.0;        // s
  bool steady = false;
  bool slice = false;
  std::string describe() const;  // one line: "outlet 8.1 vs feed 8.9 g/s (-9.4 %), holdup +0.3 %: not steady"
};

FlowSteadiness flow_steadiness(const std::vector<MassFlowSample>& log, const SceneConfig& scene, double window,
                               double tolerance);

}  // namespace centrec::dem::scene
