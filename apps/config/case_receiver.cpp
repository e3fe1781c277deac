#include "config/case_receiver.hpp"
#include "config/shared_ranges.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::config {

ReceiverSection read_receiver_section(MapReader r, bool complete) {
  auto value = [&](const char* key, Range range, const char* unit, const char* meaning) -> std::optional<double> {
    if (!complete && !r.has(key)) return std::nullopt;
    return r.required_number(key, range, unit, meaning);
  };
  ReceiverSection s;
  s.diameter = value("diameter", Range::open_closed(0.0, 100.0), "m", "the receiver's drum diameter");
  s.length = value("length", Range::open_closed(0.0, 1000.0), "m", "the receiver's drum length");
  s.speed_rpm = value("speed_rpm", shared_ranges::speed_rpm(), "rpm", "the receiver's rotational speed");
  s.mass_flow = value("mass_flow", shared_ranges::mass_flow(), "kg/s", "the receiver's particle mass flow");
  s.tilt = r.number("tilt_deg", 45.0, Range::closed(0.0, 90.0), "deg", "axis tilt from horizontal (as dem.drum.tilt_deg)") *
           M_PI / 180.0;
  s.dem_diameter_d = r.number("dem_diameter_d", 0.0, Range::closed(0.0, 1e5), "d (0 = use dem.drum as given)",
                              "derive the DEM drum by eqs 1-3 at D = this x d (docs/scaling.md)");
  // Read only when given, so a case without it resolves (and caches) as before.
  if (r.has("particle_diameter"))
    s.particle_diameter = value("particle_diameter", Range::open_closed(0.0, 1.0), "m",
                                "the particles' diameter, checked against dem.particles.diameter");
  r.finish();
  return s;
}

ReceiverCase read_receiver(MapReader r, MapReader dem) {
  const ReceiverSection s = read_receiver_section(r, true);
  ReceiverCase c;
  c.op.diameter = *s.diameter;
  c.op.length = *s.length;
  c.op.omega = coupling::rpm_to_rad_per_s(*s.speed_rpm);
  c.op.mass_flow = *s.mass_flow;
  c.tilt = s.tilt;
  c.dem_diameter_d = s.dem_diameter_d;
  c.particle_diameter = s.particle_diameter.value_or(0.0);
  if (c.dem_diameter_d > 0.0) {
    MapReader drum = dem.child("drum");
    for (const char* key : {"diameter", "length", "speed_rpm", "tilt_deg"})
      if (drum.has(key))
        r.fail("dem_diameter_d", std::string("derives the DEM drum by eqs 1-3, but dem.drum.") + key +
                                     " is also given: remove one of them");
    if (dem.child("feeder").has("mass_flow"))
      r.fail("dem_diameter_d", "derives the DEM mass flow by eq 2, but dem.feeder.mass_flow is also given");
    if (dem.child("slice").has("target_mass_flow"))
      r.fail("dem_diameter_d", "derives the DEM mass flow by eq 2, but dem.slice.target_mass_flow is also given");
    for (const char* key : {"diameter", "length", "speed_rpm", "tilt_deg"}) drum.drop_resolved(key);
    dem.child("feeder").drop_resolved("mass_flow");
    dem.child("slice").drop_resolved("target_mass_flow");
  }
  return c;
}

coupling::ReceiverOperatingPoint dem_operating_point(const DemCase& dem) {
  const auto& d = dem.scene.drum;
  return {d.diameter, d.length, d.omega, dem::scene::target_mass_flow(dem.scene)};
}

void apply_receiver(const ReceiverCase& r, DemCase& dem, bool follow_speed_and_flow) {
  auto& drum = dem.scene.drum;
  // The same bound as a DEM drum's (config::dem_run_problem): a smaller receiver holds no film.
  if (!(r.op.diameter > 20.0 * dem.scene.particle.diameter))
    throw std::invalid_argument("receiver.diameter = " + std::to_string(r.op.diameter) +
                                " m must exceed 20 particle diameters (" +
                                std::to_string(20.0 * dem.scene.particle.diameter) + " m)");
  if (r.particle_diameter > 0.0 && std::abs(r.particle_diameter - dem.scene.particle.diameter) > 1e-9 * r.particle_diameter)
    throw std::invalid_argument("receiver.particle_diameter (" + std::to_string(r.particle_diameter) +
                                " m) differs from the DEM's particle diameter (" +
                                std::to_string(dem.scene.particle.diameter) + " m): the scaling laws keep the particles");
  if (r.dem_diameter_d > 0.0) {
    const auto sim = coupling::scale_to_diameter(r.op, r.dem_diameter_d * dem.scene.particle.diameter);
    drum.diameter = sim.diameter;
    drum.length = sim.length;
    drum.omega = sim.omega;
    drum.tilt = r.tilt;
    dem::scene::set_target_mass_flow(dem.scene, sim.mass_flow);
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
  dem::scene::set_target_mass_flow(dem.scene, sim.mass_flow);
}

}  // namespace centrec::config
