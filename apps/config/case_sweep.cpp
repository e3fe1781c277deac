#include "config/case_sweep.hpp"
#include "config/shared_ranges.hpp"

namespace centrec::config {

SweepSpec read_sweep(MapReader r) {
  SweepSpec s;
  s.speed_rpm = r.numbers("speed_rpm", {}, shared_ranges::speed_rpm(), "rpm",
                          "rotational speeds of the grid, at least one (the receiver's, or the DEM drum's without one)");
  s.mass_flow = r.numbers("mass_flow", {}, shared_ranges::mass_flow(), "kg/s",
                          "mass flows of the grid, at least one (the receiver's, or the DEM feed's without one)");
  if (s.speed_rpm.empty()) r.fail("speed_rpm", "give at least one rotational speed");
  if (s.mass_flow.empty()) r.fail("mass_flow", "give at least one mass flow");
  s.parallel = static_cast<int>(r.integer("parallel", 2, 1, 256, "coupled runs at a time, one DEM thread each"));
  r.finish();
  return s;
}

}  // namespace centrec::config
