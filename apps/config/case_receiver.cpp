#include "config/case_receiver.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::config {


ReceiverCase read_receiver(MapReader r, MapReader dem) {
  ReceiverCase c;
  c.op.diameter = r.required_number("diameter", Range::open_closed(0.0, 100.0), "m");
  c.op.length = r.required_number("length", Range::open_closed(0.0, 1000.0), "m");
  c.op.omega = coupling::rpm_to_rad_per_s(r.required_number("speed_rpm", Range::open_closed(0.0, 1e5), "rpm"));
  c.op.mass_flow = r.required_number("mass_flow", Range::open_closed(0.0, 1e4), "kg/s");
  c.tilt = r.number("tilt_deg", 45.0, Range::closed(0.0, 90.0), "deg") * M_PI / 180.0;
  c.dem_diameter_d = r.number("dem_diameter_d", 0.0, Range::closed(0.0, 1e5), "d (0 = use dem.drum as given)");
  if (c.dem_diameter_d > 0.0) {
    MapReader drum = dem.child("drum");
    for (const char* key : {"diameter", "length", "speed_rpm", "tilt_deg"})
      if (drum.has(key))
        r.fail("dem_diameter_d", std::string("derives the DEM drum by eqs 1-3, but dem.drum.") + key +
                                     " is also given: remove one of them");
    if (dem.child("feeder").has("mass_flow"))
      r.fail("dem_diameter_d", "derives the DEM mass flow by eq 2, but dem.feeder.mass_flow is also given");
  }
  r.finish();
  return c;
}

coupling::ReceiverOperatingPoint dem_operating_point(const DemCase& dem) {
  const auto& d = dem.scene.drum;
  return {d.diameter, d.length, d.omega, dem.scene.feeder.mass_flow};
}

void apply_receiver(const ReceiverCase& r, DemCase& dem, bool follow_speed_and_flow) {
  auto& drum = dem.scene.drum;
  if (r.dem_diameter_d > 0.0) {
    const auto sim = coupling::scale_to_diameter(r.op, r.dem_diameter_d * dem.scene.particle.diameter);
    drum.diameter = sim.diameter;
    drum.length = sim.length;
    drum.omega = sim.omega;
    drum.tilt = r.tilt;
    dem.scene.feeder.mass_flow = sim.mass_flow;
    return;
  }
  if (std::abs(drum.tilt - r.tilt) > 1e-9)
    throw std::invalid_argument("receiver.tilt_deg (" + std::to_string(r.tilt * 180.0 / M_PI) +
                                ") differs from dem.drum.tilt_deg (" + std::to_string(drum.tilt * 180.0 / M_PI) +
                                "): the scaling laws keep the tilt");
  if (!follow_speed_and_flow) return;
  // Keep the given drum's size; its speed and feed follow the receiver by eqs 1-2.
  const auto sim = coupling::scale_to_diameter(r.op, drum.diameter);
  drum.omega = sim.omega;
  dem.scene.feeder.mass_flow = sim.mass_flow;
}

}  // namespace centrec::config
