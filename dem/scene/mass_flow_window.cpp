#include "dem/scene/mass_flow_window.hpp"

namespace centrec::dem::scene {

WindowFlows window_flows(const std::vector<MassFlowSample>& log, double window) {
  if (log.size() < 2) return {};
  const auto& last = log.back();
  std::size_t k = log.size() - 1;
  while (k > 0 && last.time - log[k].time < window) --k;
  const double dt = last.time - log[k].time;
  if (dt <= 0.0) return {};
  return {(last.fed - log[k].fed) / dt, (last.out - log[k].out) / dt};
}

}  // namespace centrec::dem::scene
