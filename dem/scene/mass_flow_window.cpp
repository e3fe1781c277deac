#include "dem/scene/mass_flow_window.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace centrec::dem::scene {

namespace {
// Index of the latest sample at least `window` before sample `end` (0 if the log is shorter).
std::size_t window_start(const std::vector<MassFlowSample>& log, double window, std::size_t end) {
  std::size_t k = end;
  while (k > 0 && log[end].time - log[k].time < window) --k;
  return k;
}
std::size_t window_start(const std::vector<MassFlowSample>& log, double window) {
  return window_start(log, window, log.size() - 1);
}

// Mean of the slice's instantaneous axial flow over samples (from, to].
double mean_axial(const std::vector<MassFlowSample>& log, std::size_t from, std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from + 1; k <= to; ++k) sum += log[k].axial_flow;
  return to > from ? sum / static_cast<double>(to - from) : 0.0;
}
}  // namespace

WindowFlows window_flows(const std::vector<MassFlowSample>& log, double window) {
  if (log.size() < 2) return {};
  const auto& last = log.back();
  const std::size_t k = window_start(log, window);
  const double dt = last.time - log[k].time;
  if (dt <= 0.0) return {};
  return {(last.fed - log[k].fed) / dt, (last.out - log[k].out) / dt, mean_axial(log, k, log.size() - 1),
          log[k].holdup, last.holdup, dt};
}

FlowSteadiness flow_steadiness(const std::vector<MassFlowSample>& log, const SceneConfig& scene, double window,
                               double tolerance) {
  FlowSteadiness s;
  s.slice = scene.slice.enabled;
  s.flow_error = std::numeric_limits<double>::infinity();
  if (log.size() < 3) return s;
  const WindowFlows w = window_flows(log, window);
  s.window = w.seconds;
  s.holdup_drift = w.holdup_start > 0.0 ? w.holdup_end / w.holdup_start - 1.0 : std::numeric_limits<double>::infinity();
  if (s.slice) {
    s.measured = w.axial;
    if (scene.slice.target_mass_flow > 0.0) {
      s.target = scene.slice.target_mass_flow;
    } else {  // no target: the first half of the window against the second
      const std::size_t k0 = window_start(log, window), k1 = window_start(log, 0.5 * window);
      s.target = mean_axial(log, k0, k1);
      s.measured = mean_axial(log, k1, log.size() - 1);
    }
  } else {
    s.measured = w.out;
    s.target = w.fed;
  }
  if (s.target > 0.0) s.flow_error = s.measured / s.target - 1.0;
  s.steady = std::abs(s.flow_error) <= tolerance && std::abs(s.holdup_drift) <= tolerance;
  if (!s.slice) {
    // A fed drum fills in a wave: its outflow rises through the feed towards an overshoot,
    // and one window astride the crossing averages to the feed with its holdup back where it
    // began. The window before must be steady too (docs/centrec_scene.md "Steady state").
    s.previous_flow_error = s.previous_holdup_drift = std::numeric_limits<double>::infinity();
    const std::size_t k1 = window_start(log, window), k0 = window_start(log, window, k1);
    const double dt = log[k1].time - log[k0].time;
    if (dt >= window * (1.0 - 1e-9)) {
      const double fed = (log[k1].fed - log[k0].fed) / dt, out = (log[k1].out - log[k0].out) / dt;
      if (fed > 0.0) s.previous_flow_error = out / fed - 1.0;
      if (log[k0].holdup > 0.0) s.previous_holdup_drift = log[k1].holdup / log[k0].holdup - 1.0;
    }
    s.steady = s.steady && std::abs(s.previous_flow_error) <= tolerance &&
               std::abs(s.previous_holdup_drift) <= tolerance;
  }
  return s;
}

std::string FlowSteadiness::describe() const {
  char line[300], error[40] = "no flow yet to compare";  // a window before the first feed or target
  if (target > 0.0) std::snprintf(error, sizeof error, "%+.1f %%", 100.0 * flow_error);
  char before[80] = "";
  if (!slice && std::isfinite(previous_flow_error))
    std::snprintf(before, sizeof before, "; the window before: %+.1f %%, holdup %+.1f %%", 100.0 * previous_flow_error,
                  100.0 * previous_holdup_drift);
  else if (!slice)
    std::snprintf(before, sizeof before, "; no window before it yet");
  std::snprintf(line, sizeof line, "%s %.4g vs %s %.4g g/s (%s), holdup %+.1f %% over %.3g s%s: %s",
                slice ? "axial flow" : "outlet", measured * 1e3, slice ? "target" : "feed", target * 1e3, error,
                100.0 * holdup_drift, window, before, steady ? "steady" : "NOT steady");
  return line;
}

}  // namespace centrec::dem::scene
