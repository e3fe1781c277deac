#include "dem/scene/centrec_scene.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dem/scene/packed_film.hpp"
#include "dem/scene/size_distribution.hpp"
#include "dem/sphere_mass.hpp"
#include "dem/scene/wall_lattice.hpp"

namespace centrec::dem::scene {

Vec3 scene_gravity(const SceneConfig& c) {
  const double g = c.gravity, tilt = c.drum.tilt;
  return {0.0, -g * std::cos(tilt), g * std::sin(tilt)};
}

namespace {

SimulationConfig engine_config(const SceneConfig& c) {
  SimulationConfig s;
  s.verbose = false;  // a scene's runs print the time-step advice themselves, once
  s.gravity = scene_gravity(c);
  s.dt = c.dt;
  s.max_impact_speed = c.max_impact_speed;
  s.drum.origin = {0.0, 0.0, 0.0};
  s.drum.axis = {0.0, 0.0, 1.0};
  s.drum.omega = c.drum.omega;
  s.wall_rolling = c.wall_rolling;
  s.threads = c.threads;
  if (c.skin > 0.0) s.skin_fraction = c.skin / SizeSampler(c.particle, 0).max_diameter();
  // The engine's automatic blow-up limit looks at the particles present at set-up; a
  // drum that starts empty has none, so derive it here from the largest feeder sphere:
  // twice the Hertz overlap of a particle-particle impact at max_impact_speed.
  const double r = 0.5 * SizeSampler(c.particle, 0).max_diameter();
  const PairConstants pp = make_pair_constants(c.particle.material, c.particle.material, c.particle_particle);
  const double m = sphere_mass(c.particle.material.density, r);
  s.blowup_overlap_fraction = std::max(0.05, 2.0 * hertz_max_overlap(0.5 * m, 0.5 * r, pp.E_eff, c.max_impact_speed) / r);
  if (c.slice.enabled) {
    s.periodic_z = true;
    s.z_lo = 0.0;
    s.z_hi = c.slice.length;
  }
  return s;
}

void check(const SceneConfig& c) {
  const double R = 0.5 * c.drum.diameter, d = c.particle.diameter;
  if (!(R > 10.0 * d)) throw std::invalid_argument("drum.diameter must exceed 20 particle diameters");
  if (c.drum.lip_height < 0.0 || c.drum.lip_height > 0.5 * R)
    throw std::invalid_argument("drum.lip_height must be in [0, R/2]");
  if (c.slice.enabled && c.drum.lip_height > 0.0)
    throw std::invalid_argument("drum.lip_height: a periodic slice has no outlet, so no lip (set it to 0)");
  if (c.slice.enabled && c.slice.length < 3.0 * d)
    throw std::invalid_argument("slice.length must be at least 3 particle diameters");
  if (c.feeder.enabled && !c.slice.enabled) {
    if (!(c.feeder.radial_offset > 0.0 && c.feeder.radial_offset < R))
      throw std::invalid_argument("feeder.radial_offset must lie inside the drum radius");
    if (c.feeder.axial_start + c.feeder.axial_length > c.drum.length)
      throw std::invalid_argument("feeder region extends past the drum length");
  }
}

}  // namespace

void CentrecScene::build_engine() {
  check(cfg_);
  sim_ = std::make_unique<Simulation>(engine_config(cfg_));
  // Two materials: every particle (glued, pre-filled, fed, slice-controlled) is made of the
  // case's particle material, every wall of the case's wall material.
  const MaterialId p = sim_->add_material(cfg_.particle.material);
  const MaterialId w = sim_->add_material(cfg_.wall_material);
  sim_->set_interaction(p, p, cfg_.particle_particle);
  sim_->set_interaction(p, w, cfg_.particle_wall);
  particle_material_ = p;
  wall_material_ = w;
  build_walls();
}

CentrecScene::CentrecScene(const SceneConfig& config, const SceneState& state) : cfg_(config) {
  build_engine();
  const bool fed = cfg_.feeder.enabled && !cfg_.slice.enabled;
  if (state.has_feeder != fed) throw std::invalid_argument("checkpoint: the feeder setting differs from the case");
  if (fed) {
    feeder_ = std::make_unique<Feeder>(cfg_, particle_material_, cfg_.seed);
    feeder_->restore(state.feeder);
  }
  sim_->import_state(state.engine);
  for (Motion m : sim_->motions()) glued_ += (m == Motion::drum);
  steps_per_batch_ = std::max<std::int64_t>(1, std::llround(cfg_.feeder.interval / sim_->dt()));
  if (state.has_controller != (cfg_.slice.enabled && cfg_.slice.target_mass_flow > 0.0))
    throw std::invalid_argument("checkpoint: the slice controller setting differs from the case");
  if (state.has_controller) {
    controller_ = std::make_unique<SliceHoldupController>(cfg_, particle_material_, sim_->time());
    controller_->restore(state.controller);
  }
  log_ = state.mass_flow_log;
  out_total_ = state.out_total;
  lost_total_ = state.lost_total;
}

SceneState CentrecScene::export_state() const {
  SceneState s;
  s.engine = sim_->export_state();
  s.has_feeder = feeder_ != nullptr;
  if (feeder_) s.feeder = feeder_->state();
  s.mass_flow_log = log_;
  s.out_total = out_total_;
  s.lost_total = lost_total_;
  s.has_controller = controller_ != nullptr;
  if (controller_) s.controller = controller_->state();
  return s;
}

CentrecScene::CentrecScene(const SceneConfig& config) : cfg_(config) {
  build_engine();
  const MaterialId p = particle_material_;

  const double R = drum_radius();
  const bool periodic = cfg_.slice.enabled;
  const double zmax = periodic ? cfg_.slice.length : cfg_.drum.length;
  if (cfg_.rough_wall.enabled) {
    for (const Vec3& c : rough_wall_centres(cfg_.rough_wall, R, 0.0, zmax, periodic)) {
      // Glued: turning rigidly with the drum.
      sim_->add_particle({p, 0.5 * cfg_.rough_wall.sphere_diameter, c, cross(Vec3{0, 0, cfg_.drum.omega}, c),
                          {0, 0, cfg_.drum.omega}, Motion::drum});
      ++glued_;
    }
  }

  if (!cfg_.initial_film.settled.empty()) {
    const InitialFilmSpec& film = cfg_.initial_film;
    // The histories are numbered glued first, then the film (dem/scene/settled_start.hpp).
    const std::int64_t first = sim_->add_particle({p, film.settled[0].radius, film.settled[0].x, film.settled[0].v,
                                                   film.settled[0].w});
    if (first != glued_) throw std::logic_error("settled start: the film's first id is not the glued count");
    for (std::size_t k = 1; k < film.settled.size(); ++k) {
      const InitialFilmSpec::Particle& q = film.settled[k];
      sim_->add_particle({p, q.radius, q.x, q.v, q.w});
    }
    sim_->preset_contact_histories(film.settled_contacts, film.settled_wall_contacts);
  } else if (cfg_.initial_film.particles > 0) {
    const std::vector<double> radii = loose_film_radii(cfg_);
    const LooseFilmRegion g = loose_film_region(cfg_);
    for (const FilmSite& s : packed_film_sites(radii, g.R, g.inset, g.z0, g.z1, g.periodic)) {
      // Rigid co-rotation.
      sim_->add_particle({p, s.radius, s.x, cross(Vec3{0, 0, cfg_.drum.omega}, s.x), {0, 0, cfg_.drum.omega}});
    }
  }

  if (cfg_.feeder.enabled && !periodic) {
    feeder_ = std::make_unique<Feeder>(cfg_, particle_material_, cfg_.seed);
    // An empty drum gives the engine nothing to advise dt from: insert the first batch
    // now (it is the first batch's feed, so advance() skips feeding once).
    if (sim_->size() == 0) {
      feeder_->feed(*sim_, cfg_.feeder.interval);
      prefed_ = true;
    }
  }
  sim_->setup();
  if (cfg_.slice.enabled && cfg_.slice.target_mass_flow > 0.0)
    controller_ = std::make_unique<SliceHoldupController>(cfg_, particle_material_, sim_->time());
  steps_per_batch_ = std::max<std::int64_t>(1, std::llround(cfg_.feeder.interval / sim_->dt()));
  record(0.0, 0.0);
}

void CentrecScene::build_walls() {
  const double R = drum_radius(), L = cfg_.drum.length, om = cfg_.drum.omega;
  const Vec3 o{0, 0, 0}, z{0, 0, 1};
  const MaterialId w = wall_material_;
  if (cfg_.slice.enabled) {
    sim_->add_wall(Wall::cylinder(o, z, R, -1e30, 1e30, om, w));
    return;
  }
  sim_->add_wall(Wall::cylinder(o, z, R, 0.0, L, om, w));
  if (cfg_.drum.back_plate) sim_->add_wall(Wall::disc(o, z, R, 0.0, om, w));
  if (cfg_.drum.lip_height > 0.0) sim_->add_wall(Wall::disc(Vec3{0, 0, L}, z, R, R - cfg_.drum.lip_height, om, w));
}

double CentrecScene::turn_period() const { return scene::turn_period(cfg_); }

const std::vector<ControllerWindow>& CentrecScene::controller_log() const {
  static const std::vector<ControllerWindow> none;
  return controller_ ? controller_->log() : none;
}

const FeederStats& CentrecScene::feeder_stats() const {
  static const FeederStats none{};
  return feeder_ ? feeder_->stats() : none;
}

std::int64_t CentrecScene::free_particles() const {
  std::int64_t n = 0;
  for (Motion m : sim_->motions()) n += (m == Motion::free);
  return n;
}

double CentrecScene::holdup_mass() const {
  double m = 0.0;
  const auto& mo = sim_->motions();
  const auto& ma = sim_->masses();
  for (std::size_t i = 0; i < mo.size(); ++i)
    if (mo[i] == Motion::free) m += ma[i];
  return m;
}

void CentrecScene::advance(double duration) {
  const double dt = sim_->dt();
  std::int64_t remaining = std::llround(duration / dt);
  const double R = drum_radius(), L = cfg_.drum.length;
  const bool periodic = cfg_.slice.enabled;
  using clock = std::chrono::steady_clock;
  const auto add_since = [](double& total, clock::time_point t0) {
    total += std::chrono::duration<double>(clock::now() - t0).count();
  };
  while (remaining > 0) {
    const std::int64_t n = std::min(remaining, steps_per_batch_);
    // (The engine's share of an insertion or removal, taking the particles into its lists
    // at the next step, is in its own times.)
    auto t0 = clock::now();
    if (feeder_ && !prefed_) feeder_->feed(*sim_, n * dt);
    prefed_ = false;
    add_since(times_.insertion, t0);
    sim_->step(n);
    remaining -= n;
    double out = 0.0, lost = 0.0;
    t0 = clock::now();
    if (!periodic) {
      // Outlet: past z = L. Lost: anything that escaped the drum some other way.
      const auto& x = sim_->positions();
      const auto& m = sim_->masses();
      const auto& mo = sim_->motions();
      std::vector<std::int64_t> gone;
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (mo[i] != Motion::free) continue;
        const bool past_outlet = x[i].z > L;
        const bool escaped = x[i].z < -R || std::hypot(x[i].x, x[i].y) > 1.5 * R;
        if (past_outlet || escaped) {
          (past_outlet ? out : lost) += m[i];
          gone.push_back(sim_->ids()[i]);
        }
      }
      if (!gone.empty()) {
        const double edited = sim_->times().list_edit;  // the engine's share is in its own times
        sim_->remove_particles(gone);
        times_.outlet -= sim_->times().list_edit - edited;
      }
    }
    add_since(times_.outlet, t0);
    t0 = clock::now();
    const double edited = sim_->times().list_edit;  // removals by the controller: the engine's times
    if (controller_) controller_->after_batch(*sim_);
    record(out, lost);
    add_since(times_.bookkeeping, t0);
    times_.bookkeeping -= sim_->times().list_edit - edited;
  }
}

void CentrecScene::record(double out_mass, double lost_mass) {
  out_total_ += out_mass;
  lost_total_ += lost_mass;
  MassFlowSample s;
  s.time = sim_->time();
  s.fed = feeder_ ? feeder_->stats().inserted_mass : 0.0;
  s.out = out_total_;
  s.lost = lost_total_;
  s.holdup = holdup_mass();
  s.particles = free_particles();
  if (cfg_.slice.enabled) s.axial_flow = slice_axial_mass_flow(*sim_, cfg_.slice.length);
  log_.push_back(s);
}

}  // namespace centrec::dem::scene
