#include "config/case_dem.hpp"

#include <cmath>

namespace centrec::config {


namespace {

dem::PairInteraction read_pair(MapReader m, const dem::PairInteraction& def) {
  dem::PairInteraction p;
  p.restitution = m.number("restitution", def.restitution, Range::open_closed(0.0, 1.0));
  p.friction = m.number("friction", def.friction, Range::non_negative());
  p.rolling_friction = m.number("rolling_friction", def.rolling_friction, Range::non_negative());
  m.finish();
  return p;
}

dem::Material read_material(MapReader& m, const dem::Material& def, bool with_density) {
  dem::Material out = def;
  out.youngs_modulus = m.number("youngs_modulus", def.youngs_modulus, Range::positive(), "Pa");
  out.poisson_ratio = m.number("poisson_ratio", def.poisson_ratio, {-1.0, 0.5, true, true});
  if (with_density) out.density = m.number("density", def.density, Range::positive(), "kg/m^3");
  return out;
}

}  // namespace

DemCase read_dem_case(MapReader root) {
  DemCase c;
  auto& s = c.scene;
  const double deg = M_PI / 180.0;

  auto part = root.child("particles");
  s.particle.diameter = part.number("diameter", s.particle.diameter, Range::positive(), "m");
  const double d = s.particle.diameter;
  s.particle.material = read_material(part, s.particle.material, true);
  const std::string dist = part.choice("size_distribution", "mono", {"mono", "uniform", "normal"});
  s.particle.distribution = dist == "mono"      ? dem::scene::SizeDistribution::mono
                            : dist == "uniform" ? dem::scene::SizeDistribution::uniform
                                                : dem::scene::SizeDistribution::normal;
  s.particle.relative_spread = part.number("relative_spread", 0.0, {0.0, 0.3, false, true});
  part.finish();

  auto wall = root.child("wall");
  s.wall_material = read_material(wall, s.wall_material, false);
  wall.finish();

  auto contacts = root.child("contacts");
  s.particle_particle = read_pair(contacts.child("particle_particle"), s.particle_particle);
  s.particle_wall = read_pair(contacts.child("particle_wall"), s.particle_wall);
  s.wall_rolling = contacts.choice("wall_rolling_model", "relative", {"relative", "liggghts"}) == "relative"
                       ? dem::WallRolling::relative
                       : dem::WallRolling::liggghts;
  contacts.finish();

  auto drum = root.child("drum");
  s.drum.diameter = drum.number("diameter", s.drum.diameter, Range::positive(), "m");
  s.drum.length = drum.number("length", s.drum.length, Range::positive(), "m");
  s.drum.tilt = drum.number("tilt_deg", 45.0, Range::closed(0.0, 90.0), "deg") * deg;
  s.drum.omega = drum.number("speed_rpm", 160.08, Range::closed(-1e5, 1e5), "rpm") * 2.0 * M_PI / 60.0;
  s.drum.back_plate = drum.boolean("back_plate", true);
  s.drum.lip_height = drum.number("outlet_lip_height_d", 0.0, Range::closed(0.0, 0.25 * s.drum.diameter / d)) * d;
  drum.finish();

  auto rough = root.child("rough_wall");
  s.rough_wall.enabled = rough.boolean("enabled", false);
  s.rough_wall.lattice = rough.choice("lattice", "square", {"square", "hexagonal"}) == "square"
                             ? dem::scene::Lattice::square
                             : dem::scene::Lattice::hexagonal;
  s.rough_wall.sphere_diameter = rough.number("sphere_diameter_d", 1.0, Range::closed(0.2, 5.0)) * d;
  s.rough_wall.spacing =
      rough.number("spacing_d", 1.0, Range::closed(s.rough_wall.sphere_diameter / d, 20.0)) * d;
  rough.finish();

  auto feed = root.child("feeder");
  s.feeder.enabled = feed.boolean("enabled", true);
  s.feeder.mass_flow = feed.number("mass_flow", s.feeder.mass_flow, Range::non_negative(), "kg/s");
  s.feeder.radial_offset = feed.number("radial_offset_d", 10.0, Range::positive()) * d;
  s.feeder.angle = feed.number("angle_deg", 0.0, Range::closed(-360.0, 360.0), "deg") * deg;
  s.feeder.axial_start = feed.number("axial_start_d", 1.0, Range::non_negative()) * d;
  s.feeder.axial_length = feed.number("axial_length_d", 5.0, Range::closed(1.0, 1e6)) * d;
  s.feeder.radial_height = feed.number("radial_height_d", 2.0, Range::closed(1.0, 1e6)) * d;
  s.feeder.arc_width = feed.number("arc_width_d", 10.0, Range::closed(1.0, 1e6)) * d;
  s.feeder.interval = feed.number("interval", 1e-3, Range::closed(1e-7, 1.0), "s");
  feed.finish();

  auto film = root.child("initial_film");
  s.initial_film.particles = film.integer("particles", 0, 0, 100000000);
  s.initial_film.axial_from = film.number("axial_from", 0.0, Range::non_negative(), "m");
  s.initial_film.axial_to = film.number("axial_to", 0.0, Range::non_negative(), "m");
  film.finish();

  auto slice = root.child("slice");
  s.slice.enabled = slice.boolean("enabled", false);
  s.slice.length = slice.number("length_d", 20.0, Range::closed(3.0, 1e5)) * d;
  s.slice.target_mass_flow = slice.number("target_mass_flow", 0.0, Range::non_negative(), "kg/s (0 = no controller)");
  s.slice.controller_gain = slice.number("controller_gain", 0.25, Range::open_closed(0.0, 2.0));
  s.slice.controller_window_turns = slice.number("controller_window_turns", 1.0, Range::closed(0.1, 1000.0), "turns");
  s.slice.controller_max_step = slice.number("controller_max_step", 0.1, Range::open_closed(0.0, 1.0));
  slice.finish();

  s.gravity = root.number("gravity", 9.81, Range::non_negative(), "m/s^2");
  s.seed = static_cast<std::uint64_t>(root.integer("seed", 12345, 0, 2147483647L));

  auto run = root.child("run");
  s.dt = run.number("dt", 0.0, Range::non_negative(), "s (0 = advised)");
  s.max_impact_speed = run.number("max_impact_speed", 2.0, Range::positive(), "m/s");
  s.threads = static_cast<int>(run.integer("threads", 0, 0, 1024));
  s.skin = run.number("skin_d", 0.2, Range::closed(0.01, 5.0), "d (Verlet skin)") * d;
  c.run.duration = run.number("duration", 1.0, Range::positive(), "s");
  c.run.max_extension =
      run.number("max_extension", -1.0, Range::closed(-1.0, 1e12), "s (spin-up extended until steady; -1 = run.duration)");
  c.run.progress_interval = run.number("progress_interval", 0.0, Range::non_negative(), "s");
  c.run.flow_window_turns = run.number("flow_window_turns", 5.0, Range::positive(), "turns");
  c.run.steady_tolerance = run.number("steady_tolerance", 0.05, Range::open_closed(0.0, 1.0));
  c.run.checkpoint_interval = run.number("checkpoint_interval", 300.0, Range::non_negative(), "s of wall time (0 = off)");
  run.finish();

  auto samp = root.child("sampling");
  c.sampling.turns = samp.number("turns", 0.0, Range::closed(0.0, 1e6), "turns");
  auto& sp = c.sampling.sampler;
  sp.snapshots_per_turn = static_cast<int>(samp.integer("snapshots_per_turn", sp.snapshots_per_turn, 1, 1000));
  sp.axial_sections = static_cast<int>(samp.integer("axial_sections", sp.axial_sections, 1, 1000));
  sp.tangential_bins = static_cast<int>(samp.integer("tangential_bins", sp.tangential_bins, 4, 3600));
  sp.bin_width_d = samp.number("bin_width_d", sp.bin_width_d, Range::closed(0.05, 5.0));
  sp.bins = static_cast<int>(samp.integer("bins", sp.bins, 1, 1000));
  sp.zone_threshold = samp.number("zone_threshold", sp.zone_threshold, Range::open_closed(0.0, 1.0));
  sp.dispersion_spacing = samp.number("dispersion_spacing", sp.dispersion_spacing, Range::closed(0.0, 1.0),
                                      "s between the dispersion's position samples (0 = one feeder batch)");
  sp.dispersion_lags = static_cast<int>(samp.integer("dispersion_lags", sp.dispersion_lags, 2, 1000));
  samp.finish();

  root.finish();
  return c;
}

}  // namespace centrec::config
