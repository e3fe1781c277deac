#pragma once
// Whether a DEM run's film was at steady flow over its sampled window, judged from the
// outlet against the feed: a sweep point is an operating point only if it was.
#include <cmath>
#include <cstdio>
#include <string>

namespace centrec::runs {

// Outlet within a factor 1.25 of the feed either way: "ok"; below 80 %: "filling" (the
// thermal model then carries the DEM's low outlet flow); above 125 %: "draining" (the film
// is still emptying its pre-fill, and the flow carried is too high).
inline std::string dem_flow_status(double outlet_kg_s, double inlet_kg_s) {
  if (outlet_kg_s < 0.8 * inlet_kg_s) return "filling";
  if (outlet_kg_s > 1.25 * inlet_kg_s) return "draining";
  return "ok";
}

// The closing line on a fed drum's flow, said plainly: outlet against inlet over the last
// window, "steady" when they agree within `tolerance` (dem.run.steady_tolerance), else
// "NOT STEADY" and which way the film is going.
inline std::string dem_flow_verdict(double outlet_kg_s, double inlet_kg_s, double window_s, double tolerance) {
  if (!(inlet_kg_s > 0.0)) return "no feed: no steady-state check";
  const double ratio = outlet_kg_s / inlet_kg_s;
  char b[320];
  std::snprintf(b, sizeof b, "outlet %.3f g/s vs inlet %.3f g/s over the last %.2f s (%.0f %% of the feed): %s",
                outlet_kg_s * 1e3, inlet_kg_s * 1e3, window_s, 100.0 * ratio,
                std::fabs(ratio - 1.0) <= tolerance
                    ? "steady"
                    : ratio < 1.0 ? "NOT STEADY, the film is still filling (run longer: dem.run.duration)"
                                  : "NOT STEADY, the film is still draining its pre-fill (run longer: dem.run.duration)");
  return std::string(b) + (std::fabs(ratio - 1.0) <= tolerance ? "" : "; steady means within " +
                                                                       std::to_string(static_cast<int>(std::lround(100 * tolerance))) +
                                                                       " % (dem.run.steady_tolerance)");
}

}  // namespace centrec::runs
