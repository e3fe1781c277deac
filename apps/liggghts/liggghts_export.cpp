#include "liggghts/liggghts_export.hpp"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/feeder.hpp"
#include "dem/scene/size_distribution.hpp"
#include "dem/sphere_mass.hpp"
#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
#include "liggghts/liggghts_data_file.hpp"
#include "liggghts/liggghts_materials.hpp"
#include "liggghts/liggghts_stl.hpp"

namespace centrec::liggghts {

namespace {

using dem::scene::SceneConfig;
using dem::scene::SizeDistribution;

// printf into a string (the deck is mostly numbers at full precision).
template <class... A>
std::string fmt(const char* f, A... a) {
  const int n = std::snprintf(nullptr, 0, f, a...);
  std::string s(static_cast<std::size_t>(n), '\0');
  std::snprintf(s.data(), s.size() + 1, f, a...);
  return s;
}

// LIGGGHTS wants every random seed a distinct prime above 10000: the smallest prime at or
// above `base` (bases far apart per use: insertion, distribution, size templates).
long prime_seed(long base) {
  for (long n = base;; ++n) {
    bool prime = n > 1;
    for (long k = 2; k * k <= n && prime; ++k) prime = n % k != 0;
    if (prime) return n;
  }
}
constexpr long kInsertSeed = 20000000, kDistributionSeed = 30000000, kTemplateSeed = 40000000;

LiggghtsBox domain(const SceneConfig& c, double dmax) {
  const double R = 0.5 * c.drum.diameter, h = 1.05 * R;
  if (c.slice.enabled) return {{-h, -h, 0.0}, {h, h, c.slice.length}};
  // Room for the back plate and the outlet face (mesh nodes must lie inside the box),
  // and for a particle that crosses the outlet face before it is deleted.
  return {{-h, -h, -2.0 * dmax}, {h, h, c.drum.length + 3.0 * dmax}};
}

// The data file: glued spheres first (ids 1..glued), then the starting film, both taken
// from the native scene's set-up so the two engines start from the same state.
std::string data_file(const dem::scene::CentrecScene& scene, const LiggghtsBox& box, LiggghtsDeckPlan& plan) {
  const auto& sim = scene.simulation();
  const double rho = scene.config().particle.material.density;
  std::vector<LiggghtsAtom> atoms;
  plan.glued = plan.initial_free = 0;
  plan.initial_holdup = 0.0;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < sim.size(); ++i) {
      const bool free = sim.motions()[i] == dem::Motion::free;
      if (free != (pass == 1)) continue;
      atoms.push_back({2.0 * sim.radii()[i], rho, sim.positions()[i], sim.velocities()[i], sim.angular_velocities()[i]});
      if (free) {
        ++plan.initial_free;
        plan.initial_holdup += sim.masses()[i];
      } else {
        ++plan.glued;
      }
    }
  const std::string g = std::to_string(scene.glued_particles());
  return liggghts_data_file("centrec starting state: " + g + " glued rough-wall spheres (ids 1.." + g +
                                "), then the starting film",
                            box, atoms);
}

// The drum mesh: facet columns within 0.1 % of a diameter of the true cylinder, facets
// about 10 times longer than wide, and the curvature that lets contact history cross from
// one facet column to the next. The deck's drum is a static mesh with a surface velocity,
// so a particle held on the smooth wall travels over the polygon: its facets' sagitta is a
// washboard of that height. The static Hertz overlap of a wall-layer particle under its
// centrifugal load is about 1e-3 d, so facets within 1e-2 d shook the stuck layer loose
// (smooth-wall lip 3 d drum: -10.3 % holdup and a wedge-shaped film against the native
// engine, -1.8 % within 1e-3 d; apps/bench/results/engine_crosscheck.md).
void plan_drum_mesh(const SceneConfig& c, double d, LiggghtsDeckPlan& plan) {
  const double R = 0.5 * c.drum.diameter;
  const double L = c.slice.enabled ? c.slice.length : c.drum.length;
  plan.drum_facets_around = facets_around(R, 1e-3 * d);
  plan.drum_facets_axial = facets_along(R, L, plan.drum_facets_around);
  plan.drum_curvature_deg = cylinder_curvature_deg(R, L, plan.drum_facets_around, plan.drum_facets_axial);
  plan.has_ends = !c.slice.enabled && (c.drum.back_plate || c.drum.lip_height > 0.0);
}

// Drum cylinder STL.
std::string drum_stl(const SceneConfig& c, const LiggghtsDeckPlan& plan) {
  const double R = 0.5 * c.drum.diameter;
  const double L = c.slice.enabled ? c.slice.length : c.drum.length;
  std::ostringstream s;
  s << "solid drum\n";
  write_cylinder_facets(s, R, 0.0, L, plan.drum_facets_around, plan.drum_facets_axial);
  s << "endsolid drum\n";
  return s.str();
}

// The drum's flat ends, a mesh of their own (their fan triangles are as thin as a facet
// column is wide, so they cannot take the cylinder's curvature): back plate, outlet lip.
std::string drum_ends_stl(const SceneConfig& c, int around) {
  const double R = 0.5 * c.drum.diameter;
  std::ostringstream s;
  s << "solid drum_ends\n";
  if (c.drum.back_plate) write_annulus_facets(s, 0.0, 0.0, R, around, true);
  if (c.drum.lip_height > 0.0) write_annulus_facets(s, c.drum.length, R - c.drum.lip_height, R, around, false);
  s << "endsolid drum_ends\n";
  return s.str();
}

// The outlet face: the open disc at z = L that counts and deletes leaving particles.
std::string outlet_stl(const SceneConfig& c, int around) {
  const double R = 0.5 * c.drum.diameter, r = R - c.drum.lip_height;
  std::ostringstream s;
  s << "solid outlet\n";
  write_annulus_facets(s, c.drum.length, 0.0, r, around, true);
  s << "endsolid outlet\n";
  return s.str();
}

// The feeder's size distribution as particle templates: mono is exact; uniform and
// (3-sigma truncated) normal become 9 equal-width size classes with number weights
// (particledistribution/discrete/numberbased), LIGGGHTS' way to express a distribution.
std::string size_templates(const dem::scene::ParticleSpec& p) {
  std::vector<std::pair<double, double>> classes;  // diameter, number weight
  const double d = p.diameter, s = p.relative_spread;
  if (p.distribution == SizeDistribution::mono || s <= 0.0) {
    classes.push_back({d, 1.0});
  } else {
    const int k = 9;
    const double half = p.distribution == SizeDistribution::uniform ? s : 3.0 * s;
    for (int i = 0; i < k; ++i) {
      const double x = -half + (i + 0.5) * 2.0 * half / k;  // relative deviation of the class centre
      const double w = p.distribution == SizeDistribution::uniform ? 1.0 : std::exp(-0.5 * (x / s) * (x / s));
      classes.push_back({d * (1.0 + x), w});
    }
  }
  double total = 0.0;
  for (const auto& c : classes) total += c.second;
  std::ostringstream t;
  t << "# Feeder sizes: " << classes.size() << " template(s) (diameter, number fraction).\n";
  for (std::size_t i = 0; i < classes.size(); ++i)
    t << fmt("fix size%zu film particletemplate/sphere %ld atom_type 1 density constant %.9g radius constant %.17g\n",
             i, prime_seed(kTemplateSeed + 1000 * static_cast<long>(i)), p.material.density, 0.5 * classes[i].first);
  t << fmt("fix sizes film particledistribution/discrete/numberbased %ld %zu", prime_seed(kDistributionSeed), classes.size());
  for (std::size_t i = 0; i < classes.size(); ++i) t << fmt(" size%zu %.9g", i, classes[i].second / total);
  t << "\n";
  return t.str();
}

// Sub-sectors of the feeder: LIGGGHTS gives all particles of one insertion fix the same
// velocity vector, so the sector is split into parts of at most 20 deg, each fed at its
// share of the mass flow with the wall's tangent at its own centre (direction within 10 deg
// of the native feeder's per-particle tangent).
int feeder_parts(double arc_angle) { return std::max(1, static_cast<int>(std::ceil(arc_angle / (20.0 * M_PI / 180.0)))); }

// Where the feeder may put the centres of its largest particles (the native feeder's range),
// centred on the feeder's sector and never below 2 % of d across (a LIGGGHTS region needs room).
struct FeederCentres {
  double r_in, r_out, z0, z1, a0, arc;
};

FeederCentres feeder_centres(const SceneConfig& c) {
  const auto& f = c.feeder;
  const double r = 0.5 * dem::scene::SizeSampler(c.particle, 0).max_diameter(), m = 0.01 * c.particle.diameter;
  const dem::scene::FeederCentreRange range = dem::scene::feeder_centre_range(c, r);
  const double rc = range.rc;
  const double hr = std::max(m, 0.5 * range.radial_width), hz = std::max(m, 0.5 * range.axial_width);
  const double arc = std::min(2.0 * M_PI, std::max(m / rc, range.arc_length / rc));
  const double zc = f.axial_start + 0.5 * f.axial_length;
  return {rc - hr, rc + hr, zc - hz, zc + hz, f.angle - 0.5 * arc, arc};
}

std::string feeder_commands(const SceneConfig& c, const LiggghtsDeckPlan& plan, double total_time) {
  const auto& f = c.feeder;
  const FeederCentres fc = feeder_centres(c);
  const double arc = fc.arc;
  const double speed = c.drum.omega * 0.5 * c.drum.diameter;  // the wall's linear speed, signed with the spin
  const int parts = feeder_parts(arc);
  std::ostringstream s;
  s << "\n# --- Feeder (docs/centrec_scene.md): an annular sector centred radial_offset inside the wall,\n"
       "# r in [rc - h/2, rc + h/2], theta within arc_width/(2 rc) of the feeder angle, z in\n"
       "# [axial_start, axial_start + axial_length]; particles enter at the mass flow rate with the\n"
       "# wall's tangential speed omega R and no axial velocity. One LIGGGHTS insertion gives all\n"
       "# its particles one velocity, so the sector is split into "
    << parts << " part(s) of equal angle, each fed at\n"
       "# its share of the rate with the tangent at its centre. The regions hold the particle\n"
       "# centres (the sector shrunk by the largest radius, as the native feeder places them), so\n"
       "# all_in is off. maxattempt = feeder.max_attempts.\n";
  s << size_templates(c.particle);
  s << fmt("region feed_outer cylinder z 0 0 %.17g %.17g %.17g side in units box\n", fc.r_out, fc.z0, fc.z1);
  s << fmt("region feed_inner cylinder z 0 0 %.17g %.17g %.17g side out units box\n", fc.r_in, fc.z0, fc.z1);
  for (int k = 0; k < parts; ++k) {
    const double a0 = fc.a0 + k * arc / parts, a1 = a0 + arc / parts, am = 0.5 * (a0 + a1);
    // A wedge of less than 180 deg: the intersection of two half-planes through the axis
    // (a plane region's inside is where its normal points).
    s << fmt("region feed%d_a plane 0 0 0 %.17g %.17g 0 side in units box\n", k, -std::sin(a0), std::cos(a0));
    s << fmt("region feed%d_b plane 0 0 0 %.17g %.17g 0 side in units box\n", k, std::sin(a1), -std::cos(a1));
    s << fmt("region feeder%d intersect 4 feed_outer feed_inner feed%d_a feed%d_b units box\n", k, k, k);
    // The total mass is an upper bound (rate x whole run + 5 %): insertion never runs out.
    s << fmt("fix feed%d film insert/rate/region seed %ld distributiontemplate sizes mass %.9g massrate %.17g "
             "insert_every %lld overlapcheck yes all_in no maxattempt %d vel constant %.17g %.17g 0 "
             "region feeder%d ntry_mc 10000\n",
             k, prime_seed(kInsertSeed + 1000 * k), (1.05 * f.mass_flow * total_time + 1e-9) / parts,
             f.mass_flow / parts, static_cast<long long>(plan.flow_every), f.max_attempts, -std::sin(am) * speed,
             std::cos(am) * speed, k);
  }
  return s.str();
}

// "f_feed0[2]+f_feed1[2]+...": the mass inserted by all feeder parts.
std::string fed_mass_expression(const SceneConfig& c) {
  const int parts = feeder_parts(feeder_centres(c).arc);
  std::string e;
  for (int k = 0; k < parts; ++k) e += (k ? "+f_feed" : "f_feed") + std::to_string(k) + "[2]";
  return e;
}

std::string deck(const config::CaseFile& cf, const config::DemCase& dc, const LiggghtsDeckPlan& plan) {
  const SceneConfig& c = dc.scene;
  const bool slice = c.slice.enabled, fed = c.feeder.enabled && !slice;
  const double W = c.drum.omega, d = c.particle.diameter;
  const dem::Vec3 g = dem::scene::scene_gravity(c);
  const double gmag = std::sqrt(g.y * g.y + g.z * g.z);
  const double total_time = (plan.spinup_steps + plan.sampling_steps) * plan.dt;
  std::ostringstream s;
  s << "# LIGGGHTS 3.8 deck for the centrec case " << cf.path << " (" << cf.title << "),\n"
    << "# written by `centrec export-liggghts` (centrec " << centrec::io::code_version() << "). SI units.\n"
    << "# Frame (docs/centrec_scene.md): drum axis +z from the back plate (z = 0) to the outlet\n"
    << "# (z = L); gravity g (0, -cos tilt, sin tilt); the drum spins at omega about +z.\n"
    << fmt("# D = %.9g m, L = %.9g m, omega = %.9g rad/s, d = %.9g m, dt = %.9g s, %s mode.\n", c.drum.diameter,
           slice ? c.slice.length : c.drum.length, W, d, plan.dt, slice ? "periodic-slice" : "drum")
    << "# Run: mpirun -np N liggghts -in " << plan.deck << "  (from this directory)\n";
  for (const std::string& diff : plan.differences) s << "# Differs from the native engine: " << diff << ".\n";
  s << "\n";
  s << "atom_style granular\n"
       "atom_modify map array            # fix massflow/mesh deletes atoms by tag\n"
    << (slice ? "boundary f f p                   # periodic along the slice's axis\n"
              : "boundary f f f\n")
    << "newton off\n"
       "communicate single vel yes        # shear history needs ghost velocities\n"
       "units si\n"
       "processors 1 1 *                 # split along the drum axis: the film lies on the wall\n"
    << "read_data " << plan.data << "\n"
    << fmt("neighbor %.9g bin\nneigh_modify delay 0\n", c.skin > 0.0 ? c.skin : 0.2 * d);

  std::string rolling = dem::rolling_model_info(c.particle_particle.rolling_model).name;
  for (char& ch : rolling) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  s << "\n# --- Materials and contact law: type 1 particles (free and glued), type 2 the drum mesh.\n"
    << "# Hertz normal, Mindlin tangential with history, " << rolling << " rolling friction (docs/dem_physics.md).\n"
       "# LIGGGHTS' rolling model sees a particle's absolute angular velocity at a wall contact,\n"
       "# the case's `wall_rolling_model: liggghts`.\n";
  LiggghtsMaterials m;
  m.particle_youngs_modulus = c.particle.material.youngs_modulus;
  m.particle_poisson_ratio = c.particle.material.poisson_ratio;
  m.wall_youngs_modulus = c.wall_material.youngs_modulus;
  m.wall_poisson_ratio = c.wall_material.poisson_ratio;
  m.particle_particle = c.particle_particle;
  m.particle_wall = c.particle_wall;
  s << liggghts_material_commands(m) << fmt("timestep %.17g\n", plan.dt);

  s << "\n# --- Groups: the glued rough-wall spheres (ids 1.." << plan.glued << ") move with the drum;\n"
       "# `film` (everything else, and every inserted particle) is integrated.\n";
  if (plan.glued > 0) {
    s << fmt("group glued id <= %lld\n", static_cast<long long>(plan.glued)) << "group film subtract all glued\n";
  } else {
    s << "group film type 1\n";
  }

  s << "\n# --- The drum: still, axisymmetric meshes (cylinder" << (!slice && c.drum.back_plate ? ", back plate" : "")
    << (!slice && c.drum.lip_height > 0.0 ? ", outlet lip" : "")
    << ") written from the analytic\n"
       "# geometry, their surface moving as if rotating (surface_ang_vel). A surface of revolution\n"
       "# spinning about its own axis occupies the same space at every instant, so moving the mesh\n"
       "# (move/mesh) would only re-bin its triangles every step for the same contacts.\n"
    << fmt("# The cylinder's %d facet columns turn by %.4g deg each: `curvature %.4g` (default 0.256 deg)\n"
           "# makes LIGGGHTS carry a contact's tangential and rolling history from one column to the\n"
           "# next, as on the true cylinder, instead of restarting it at every column.\n",
           plan.drum_facets_around, 360.0 / plan.drum_facets_around, plan.drum_curvature_deg)
    << fmt("fix drum all mesh/surface file %s type 2 curvature %.6g surface_ang_vel origin 0 0 0 axis 0 0 1 omega %.17g\n",
           plan.drum_stl.c_str(), plan.drum_curvature_deg, W);
  if (plan.has_ends)
    s << fmt("fix drum_ends all mesh/surface file %s type 2 surface_ang_vel origin 0 0 0 axis 0 0 1 omega %.17g\n",
             plan.ends_stl.c_str(), W);
  s << "fix walls film wall/gran " << liggghts_contact_model(c.particle_wall)
    << (plan.has_ends ? " mesh n_meshes 2 meshes drum drum_ends\n" : " mesh n_meshes 1 meshes drum\n");
  if (plan.glued > 0) {
    // fix move rotates right-handed about its axis with a positive period.
    s << "# Rough wall: the glued spheres rotate rigidly with the drum (prescribed motion).\n"
      << fmt("fix spin glued move rotate 0 0 0 0 0 %d %.17g\n", W >= 0.0 ? 1 : -1, 2.0 * M_PI / std::fabs(W));
  }
  s << "fix integrate film nve/sphere\n"
    << fmt("fix gravity film gravity %.17g vector %.17g %.17g %.17g\n", gmag, g.x / gmag, g.y / gmag, g.z / gmag);

  if (fed) {
    s << feeder_commands(c, plan, total_time);
    s << "\n# --- Outlet: particles crossing the open disc at z = L are counted and deleted.\n"
      << fmt("fix outlet_face all mesh/surface file %s type 2\n", plan.outlet_stl.c_str())
      << "fix outlet film massflow/mesh mesh outlet_face vec_side 0 0 1 count once delete_atoms yes\n";
  }

  s << "\n# --- Mass-flow record every feeder interval: time, fed, out (kg, cumulative), holdup (kg), free\n"
       "# particles, a slice's axial flow sum(m v_z) / L (kg/s; 0 for a drum). Atoms lost through the box\n"
       "# (none expected) show as holdup missing from the balance.\n"
       "variable t equal step*dt\n"
    << (fed ? "variable fed equal " + fed_mass_expression(c) + "\nvariable out equal f_outlet[1]\n"
            : std::string("variable fed equal 0\nvariable out equal 0\n"))
    << "variable holdup equal mass(film)\n"
       "variable nfilm equal count(film)\n"
    << (slice ? "variable mvz atom mass*vz\ncompute mvz film reduce sum v_mvz\n" +
                    fmt("variable axial equal c_mvz/%.17g\n", c.slice.length)
              : std::string("variable axial equal 0\n"))
    << fmt("fix flowlog all print %lld \"${t} ${fed} ${out} ${holdup} ${nfilm} ${axial}\" file %s screen no\n",
           static_cast<long long>(plan.flow_every), plan.flow_file.c_str())
    // The slice's compute in the thermo output keeps it current at the end of each run, where
    // the final print reads it.
    << fmt("thermo_style custom step atoms ke%s\nthermo %lld\nthermo_modify lost warn norm no\n",
           slice ? " c_mvz" : "", static_cast<long long>(std::max<std::int64_t>(plan.flow_every, plan.dump_every)));

  s << fmt("\n# --- Spin-up: run.duration (%.9g s) rounded up to whole snapshot intervals.\n", dc.run.duration)
    << "print \"CENTREC_PHASE spinup\"\n"
    << fmt("run %lld\n", static_cast<long long>(plan.spinup_steps));
  s << fmt("\n# --- Sampling: %d turn(s), %d film snapshots per turn (every %lld steps), free particles only.\n",
           plan.sampled_turns, plan.snapshots_per_turn, static_cast<long long>(plan.dump_every))
    << "print \"CENTREC_PHASE sampling\"\n"
    << fmt("dump film film custom %lld %s id radius x y z vx vy vz\n", static_cast<long long>(plan.dump_every),
           plan.dump_pattern.c_str())
    << "dump_modify film pad 12 sort id\n"
    << fmt("run %lld\n", static_cast<long long>(plan.sampling_steps))
    << "# The state at the last step (the record above is written every feeder interval only).\n"
       "print \"CENTREC_FINAL ${t} ${fed} ${out} ${holdup} ${nfilm} ${axial}\"\n"
       "print \"CENTREC_PHASE done\"\n";
  return s.str();
}

}  // namespace

std::vector<std::string> liggghts_inexpressible(const config::DemCase& dc) {
  std::vector<std::string> why;
  const SceneConfig& c = dc.scene;
  if (c.wall_rolling == dem::WallRolling::relative)
    why.push_back(
        "contacts.wall_rolling_model: relative - LIGGGHTS 3.8 mesh walls pass only a linear wall velocity, so its "
        "rolling friction sees the particle's absolute angular velocity; set `wall_rolling_model: liggghts` (or "
        "pass --wall-rolling-model liggghts) to run the same physics on both engines");
  for (const auto& [key, pair] : {std::pair{"particle_particle", &c.particle_particle}, std::pair{"particle_wall", &c.particle_wall}})
    if (!dem::rolling_model_info(pair->rolling_model).liggghts) {
      const std::string name = dem::rolling_model_info(pair->rolling_model).name;
      why.push_back(std::string("contacts.") + key + ".rolling_model: " + name + " - LIGGGHTS 3.8 has no " + name +
                    " rolling model (its rolling_friction offers " + liggghts_rolling_models() +
                    "); choose one of those or run on the native engine");
    }
  if (c.drum.omega == 0.0) why.push_back("drum.speed_rpm: 0 - the deck's rotating wall needs a non-zero speed");
  if (!dc.initial_film_from_run.empty())
    why.push_back("initial_film.from_run - the deck starts from the case's own starting film (initial_film.particles)");
  if (c.feeder.enabled && !c.slice.enabled && c.feeder.radial_offset <= 0.5 * c.feeder.radial_height)
    why.push_back("feeder.radial_height_d - the feeder sector reaches the drum axis (not a LIGGGHTS region)");
  return why;
}

std::vector<std::string> liggghts_differences(const config::DemCase& dc) {
  std::vector<std::string> d;
  const SceneConfig& c = dc.scene;
  if (c.slice.enabled && c.slice.target_mass_flow > 0.0)
    d.push_back(fmt("the slice's holdup controller (target %.4g g/s, dem.slice.controller_window_turns) is not in "
                    "the deck: LIGGGHTS runs the starting holdup unchanged, where the native run adds or removes "
                    "particles until the slice carries the target",
                    1e3 * c.slice.target_mass_flow));
  return d;
}

LiggghtsDeckPlan export_liggghts(const config::CaseFile& cf, const config::DemCase& dc, const std::string& dir,
                                 const dem::scene::SceneState* start) {
  const auto why = liggghts_inexpressible(dc);
  if (!why.empty()) {
    std::string msg = "cannot express this case in LIGGGHTS 3.8:";
    for (const auto& w : why) msg += "\n  " + w;
    throw std::invalid_argument(msg);
  }
  io::ensure_directory(dir);
  SceneConfig c = dc.scene;
  c.threads = 1;  // the set-up only: its starting particles and resolved dt
  const dem::scene::CentrecScene scene = start ? dem::scene::CentrecScene(c, *start) : dem::scene::CentrecScene(c);
  LiggghtsDeckPlan plan;
  plan.differences = liggghts_differences(dc);
  plan.dt = scene.simulation().dt();
  const double period = dem::scene::turn_period(c);
  plan.snapshots_per_turn = dc.sampling.sampler.snapshots_per_turn;
  plan.sampled_turns = static_cast<int>(std::floor(dc.sampling.turns + 1e-9));
  plan.dump_every = std::max<std::int64_t>(1, std::llround(period / plan.snapshots_per_turn / plan.dt));
  plan.flow_every = std::max<std::int64_t>(1, std::llround(c.feeder.interval / plan.dt));
  const std::int64_t spin = std::llround(dc.run.duration / plan.dt);
  plan.spinup_steps = (spin + plan.dump_every - 1) / plan.dump_every * plan.dump_every;
  plan.sampling_steps = static_cast<std::int64_t>(plan.sampled_turns) * plan.snapshots_per_turn * plan.dump_every;
  const double dmax = dem::scene::SizeSampler(c.particle, 0).max_diameter();
  const LiggghtsBox box = domain(c, dmax);
  io::write_text_atomically(dir + "/" + plan.data, data_file(scene, box, plan));
  plan_drum_mesh(c, c.particle.diameter, plan);
  io::write_text_atomically(dir + "/" + plan.drum_stl, drum_stl(c, plan));
  if (plan.has_ends) io::write_text_atomically(dir + "/" + plan.ends_stl, drum_ends_stl(c, plan.drum_facets_around));
  if (c.feeder.enabled && !c.slice.enabled)
    io::write_text_atomically(dir + "/" + plan.outlet_stl, outlet_stl(c, plan.drum_facets_around));
  io::ensure_directory(dir + "/" + plan.dump_dir);
  io::write_text_atomically(dir + "/" + plan.deck, deck(cf, dc, plan));
  return plan;
}

}  // namespace centrec::liggghts
