#include "config/case_dem.hpp"

#include "config/case_thermal.hpp"
#include "config/shared_ranges.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace centrec::config {


namespace {

dem::PairInteraction read_pair(MapReader m, const dem::PairInteraction& def) {
  dem::PairInteraction p;
  p.restitution = m.number("restitution", def.restitution, Range::open_closed(0.0, 1.0), "",
                           "coefficient of restitution of a normal impact (docs/dem_physics.md)");
  p.friction = m.number("friction", def.friction, Range::non_negative(), "",
                        "sliding friction coefficient: the Coulomb cap of the tangential force");
  p.rolling_friction = m.number("rolling_friction", def.rolling_friction, Range::non_negative(), "",
                                "rolling friction coefficient mu_r of the rolling model");
  std::vector<std::string> models;
  std::string about = "rolling resistance model (dem/rolling_models.hpp):";
  for (const dem::RollingModelInfo& i : dem::kRollingModels) {
    models.push_back(i.name);
    about += std::string(" ") + i.name + ", " + i.summary + ";";
  }
  about.pop_back();
  const std::string model = m.choice("rolling_model", dem::rolling_model_info(def.rolling_model).name, models, about);
  dem::rolling_model_named(model, p.rolling_model);
  // The model's own coefficients, keys beside rolling_model (another model's are unknown keys).
  dem::for_each_rolling_coefficient(p.rolling_model, [&](std::size_t k, const dem::RollingCoefficient& c) {
    const double fallback = def.rolling_model == p.rolling_model ? def.rolling_coefficients[k] : c.fallback;
    const double highest = c.highest < dem::kInfinity ? c.highest : std::numeric_limits<double>::infinity();
    p.rolling_coefficients[k] = m.number(c.key, fallback, {c.lowest, highest, c.lowest_open, false}, c.unit, c.meaning);
  });
  m.finish();
  return p;
}

dem::Material read_material(MapReader& m, const dem::Material& def, bool with_density) {
  dem::Material out = def;
  out.youngs_modulus = m.number("youngs_modulus", def.youngs_modulus, Range::positive(), "Pa",
                                "Young's modulus (Hertz contact stiffness)");
  out.poisson_ratio = m.number("poisson_ratio", def.poisson_ratio, {-1.0, 0.5, true, true}, "", "Poisson ratio");
  if (with_density)
    out.density = m.number("density", def.density, Range::positive(), "kg/m^3", "solid density of a particle");
  return out;
}

}  // namespace

DemCase read_dem_case(MapReader root) {
  DemCase c;
  auto& s = c.scene;
  const double deg = M_PI / 180.0;

  auto part = root.child("particles", "the free particles (paper Table 1 defaults)");
  s.particle.diameter = part.number("diameter", s.particle.diameter, Range::positive(), "m",
                                    "mean particle diameter d: the unit of every `_d` key");
  const double d = s.particle.diameter;
  s.particle.material = read_material(part, s.particle.material, true);
  const std::string dist = part.choice("size_distribution", "mono", {"mono", "uniform", "normal"},
                                       "what the feeder and the initial film draw diameters from");
  s.particle.distribution = dist == "mono"      ? dem::scene::SizeDistribution::mono
                            : dist == "uniform" ? dem::scene::SizeDistribution::uniform
                                                : dem::scene::SizeDistribution::normal;
  s.particle.relative_spread =
      part.number("relative_spread", 0.0, {0.0, 0.3, false, true}, "",
                  "uniform: half-width / mean diameter; normal: standard deviation / mean, cut at 3 sigma");
  part.finish();

  auto wall = root.child("wall", "the drum wall's material");
  s.wall_material = read_material(wall, s.wall_material, false);
  wall.finish();

  auto contacts = root.child("contacts", "pair interactions (Hertz-Mindlin and a rolling model, docs/dem_physics.md)");
  s.particle_particle = read_pair(contacts.child("particle_particle", "particle-particle contacts"), s.particle_particle);
  s.particle_wall = read_pair(contacts.child("particle_wall", "particle-wall contacts"), s.particle_wall);
  s.wall_rolling = contacts.choice("wall_rolling_model", "relative", {"relative", "liggghts"},
                                   "rolling at walls sees the spin relative to the wall (physical) or the absolute "
                                   "spin, as LIGGGHTS 3.8 mesh walls do") == "relative"
                       ? dem::WallRolling::relative
                       : dem::WallRolling::liggghts;
  contacts.finish();

  auto drum = root.child("drum", "the rotating drum (docs/centrec_scene.md)");
  s.drum.diameter = drum.number("diameter", s.drum.diameter, Range::positive(), "m", "inner drum diameter D");
  s.drum.length = drum.number("length", s.drum.length, Range::positive(), "m", "drum length L, inlet to outlet");
  s.drum.tilt = drum.number("tilt_deg", 45.0, Range::closed(0.0, 90.0), "deg", "axis tilt from horizontal") * deg;
  s.drum.omega = drum.number("speed_rpm", 160.08, Range::closed(-1e5, 1e5), "rpm",
                             "rotational speed (non-zero; the sign is the sense of rotation)") *
                 2.0 * M_PI / 60.0;
  s.drum.back_plate = drum.boolean("back_plate", true, "a disc closes the inlet end");
  s.drum.lip_height = drum.number("outlet_lip_height_d", 0.0, Range::closed(0.0, 0.25 * s.drum.diameter / d), "d",
                                  "radial height of an annular weir at the outlet (0 = open outlet; at most D/4; "
                                  "full drum only)") *
                      d;
  drum.finish();

  auto rough = root.child("rough_wall", "a monolayer of spheres glued to the rotating wall");
  s.rough_wall.enabled = rough.boolean("enabled", false, "glue the monolayer to the wall");
  s.rough_wall.lattice = rough.choice("lattice", "square", {"square", "hexagonal"},
                                      "square rows, or hexagonal rows with every other row shifted") == "square"
                             ? dem::scene::Lattice::square
                             : dem::scene::Lattice::hexagonal;
  s.rough_wall.sphere_diameter =
      rough.number("sphere_diameter_d", 1.0, Range::closed(0.2, 5.0), "d", "diameter of a glued sphere") * d;
  s.rough_wall.spacing = rough.number("spacing_d", 1.0, Range::closed(s.rough_wall.sphere_diameter / d, 20.0), "d",
                                      "centre distance of neighbouring glued spheres (at least sphere_diameter_d)") *
                         d;
  rough.finish();

  auto feed = root.child("feeder", "the region near the inlet where particles are inserted");
  s.feeder.enabled = feed.boolean("enabled", true, "insert particles (ignored by a slice)");
  s.feeder.mass_flow = feed.number("mass_flow", s.feeder.mass_flow, Range::non_negative(), "kg/s",
                                   "feed mass flow (0 = none; otherwise at least one particle per drum turn)");
  s.feeder.radial_offset = feed.number("radial_offset_d", 10.0, Range::positive(), "d",
                                       "distance of the region's centre inside the wall") *
                           d;
  s.feeder.angle = feed.number("angle_deg", 0.0, Range::closed(-360.0, 360.0), "deg",
                               "angle atan2(y, x) of the region's centre") *
                   deg;
  s.feeder.axial_start = feed.number("axial_start_d", 1.0, Range::non_negative(), "d",
                                     "start of the region from the back plate") *
                         d;
  s.feeder.axial_length = feed.number("axial_length_d", 5.0, Range::closed(1.0, 1e6), "d", "axial length of the region") * d;
  s.feeder.radial_height =
      feed.number("radial_height_d", 2.0, Range::closed(1.0, 1e6), "d", "radial height of the region") * d;
  s.feeder.arc_width = feed.number("arc_width_d", 10.0, Range::closed(1.0, 1e6), "d", "arc width of the region") * d;
  s.feeder.interval = feed.number("interval", 1e-3, Range::closed(1e-7, 1.0), "s", "time between insertion batches");
  feed.finish();

  auto film = root.child("initial_film", "a loose co-rotating film to start from (slices always fill their period)");
  s.initial_film.particles = film.integer("particles", 0, 0, 100000000, "particles placed at the start (0 = start empty)");
  s.initial_film.axial_from = film.number("axial_from", 0.0, Range::non_negative(), "m", "axial start of the film");
  s.initial_film.axial_to = film.number("axial_to", 0.0, Range::non_negative(), "m", "axial end of the film (0 = drum length)");
  c.initial_film_from_run = film.string(
      "from_run", "",
      "a settled start: the film of that `centrec dem` run's last state (its folder, with checkpoint.h5, relative to "
      "the case file), a slice's laid end to end or a drum's, on the same drum diameter and rough wall");
  if (!c.initial_film_from_run.empty() && s.initial_film.particles > 0)
    film.fail("from_run", "and initial_film.particles both given: a settled start replaces the loose film");
  s.initial_film.holdup_fraction =
      film.number("holdup_fraction", 1.0, Range::open_closed(0.0, 1.0), "",
                  "with from_run: the fraction of the laid film kept in every axial section of one diameter, its "
                  "top left out (a fed drum of the paper's length holds about 0.75 of its slice's film)");
  if (s.initial_film.holdup_fraction < 1.0 && c.initial_film_from_run.empty())
    film.fail("holdup_fraction", "thins a settled start: give initial_film.from_run with it");
  film.finish();

  auto slice = root.child("slice", "an axially periodic slice of the drum instead of the full drum");
  s.slice.enabled = slice.boolean("enabled", false, "simulate a periodic slice: no feeder, outlet or plates");
  s.slice.length = slice.number("length_d", 20.0, Range::closed(3.0, 1e5), "d", "axial period of the slice") * d;
  s.slice.target_mass_flow = slice.number("target_mass_flow", 0.0, Range::non_negative(), "kg/s (0 = no controller)",
                                          "axial mass flow the holdup controller steers to");
  s.slice.controller_gain = slice.number("controller_gain", 0.25, Range::open_closed(0.0, 2.0), "",
                                         "holdup change per window = gain x ln(target / flow) x holdup");
  s.slice.controller_window_turns = slice.number("controller_window_turns", 1.0, Range::closed(0.1, 1000.0), "turns",
                                                 "drum turns per controller measurement window");
  s.slice.controller_max_step = slice.number("controller_max_step", 0.1, Range::open_closed(0.0, 1.0), "",
                                             "largest holdup change per window, as a fraction of the holdup");
  slice.finish();

  s.gravity = root.number("gravity", 9.81, Range::positive(), "m/s^2",
                          "gravitational acceleration (> 0: its part across the axis sets the film's top)");
  s.seed = static_cast<std::uint64_t>(
      root.integer("seed", 12345, 0, shared_ranges::kSeedMax, "random seed of the feeder and the initial film"));

  auto run = root.child("run", "time stepping, run length, threads, progress and checkpoints");
  s.dt = run.number("dt", 0.0, Range::non_negative(), "s (0 = advised)",
                    "time step; at most the stability bound the run prints");
  s.max_impact_speed = run.number("max_impact_speed", 2.0, Range::positive(), "m/s",
                                  "impact speed the time-step advice and blow-up check assume");
  s.threads = static_cast<int>(run.integer("threads", 0, 0, shared_ranges::kThreadsMax, "OpenMP threads (0 = all cores)"));
  s.skin = run.number("skin_d", 0.2, Range::closed(0.01, 5.0), "d (Verlet skin)",
                      "neighbour-list margin beyond contact") *
           d;
  c.run.duration = run.number("duration", 1.0, shared_ranges::duration(), "s", "simulated spin-up time before sampling");
  c.run.max_extension =
      run.number("max_extension", -1.0, Range::closed(-1.0, 1e12), "s (spin-up extended until steady; -1 = run.duration)",
                 "longest extension of the spin-up past run.duration while the flow is not steady");
  c.run.progress_interval = run.number("progress_interval", 0.0, Range::non_negative(), "s",
                                       "wall time between progress lines (0 = every 2 s on a terminal, about every 10 % otherwise)");
  c.run.flow_window_turns = run.number("flow_window_turns", 5.0, Range::positive(), "turns",
                                       "drum turns over which inlet and outlet flows are averaged");
  c.run.steady_tolerance = run.number("steady_tolerance", 0.05, Range::open_closed(0.0, 1.0), "",
                                      "relative outlet-feed and holdup change that counts as steady flow");
  c.run.checkpoint_interval = run.number("checkpoint_interval", 300.0, Range::non_negative(), "s of wall time (0 = off)",
                                         "wall time between writes of DIR/checkpoint.h5");
  run.finish();

  auto samp = root.child("sampling", "the film samplers after the spin-up (docs/film_sampling.md)");
  c.sampling.turns = samp.number("turns", 0.0, Range::closed(0.0, 1e6), "turns",
                                 "drum turns sampled after the spin-up (0 = no film fields)");
  auto& sp = c.sampling.sampler;
  sp.snapshots_per_turn = static_cast<int>(
      samp.integer("snapshots_per_turn", sp.snapshots_per_turn, 1, 1000, "snapshots the samplers take per turn"));
  sp.axial_sections = static_cast<int>(
      samp.integer("axial_sections", sp.axial_sections, 1, 1000, "axial sections of the thickness and ring profiles"));
  sp.tangential_bins = static_cast<int>(
      samp.integer("tangential_bins", sp.tangential_bins, 4, 3600, "tangential bins around the circumference"));
  sp.bin_width_d = samp.number("bin_width_d", sp.bin_width_d, Range::closed(0.05, 5.0), "d",
                               "width of a wall-distance bin of the profiles");
  sp.bins = static_cast<int>(samp.integer("bins", sp.bins, 1, 1000, "wall-distance bins of the profiles"));
  sp.zone_threshold = samp.number("zone_threshold", sp.zone_threshold, Range::open_closed(0.0, 1.0), "",
                                  "moving zone: surface axial velocity above this fraction of its maximum");
  sp.dispersion_spacing = samp.number("dispersion_spacing", sp.dispersion_spacing, Range::closed(0.0, 1.0), "s",
                                      "time between the dispersion's position samples (0 = one feeder batch)");
  sp.dispersion_lags = static_cast<int>(samp.integer("dispersion_lags", sp.dispersion_lags, 2, 1000,
                                                     "the fine series' longest lag, in sample spacings (docs/film_sampling.md)"));
  samp.finish();

  root.finish();
  return c;
}

std::string settled_start_dir(const std::string& case_path, const DemCase& dc) {
  const std::string& dir = dc.initial_film_from_run;
  const std::string case_dir = case_directory(case_path);
  return !dir.empty() && dir[0] != '/' && !case_dir.empty() ? case_dir + "/" + dir : dir;
}

}  // namespace centrec::config
