#pragma once
// Whether a DEM run's film was at steady flow over its sampled window, judged from the
// outlet against the feed: a sweep point is an operating point only if it was.
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

}  // namespace centrec::runs
