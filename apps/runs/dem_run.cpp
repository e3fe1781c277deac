#include "runs/dem_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "config/case_checks.hpp"
#include "config/strict_yaml.hpp"
#include "dem/scene/feeder.hpp"
#include "dem/scene/mass_flow_window.hpp"
#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
#include "runs/settled_start.hpp"

namespace centrec::runs {

namespace {
// The glued rough-wall layer (Motion::drum) in the snapshot layout, for the outputs only.
dem::scene::SnapshotArrays glued_layer(const dem::Simulation& sim) {
  dem::scene::SnapshotArrays s;
  s.time = sim.time();
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (sim.motions()[i] == dem::Motion::free) continue;
    const dem::Vec3 x = sim.positions()[i], v = sim.velocities()[i];
    s.x.push_back(x.x), s.y.push_back(x.y), s.z.push_back(x.z);
    s.vx.push_back(v.x), s.vy.push_back(v.y), s.vz.push_back(v.z);
    s.radius.push_back(sim.radii()[i]);
    s.id.push_back(sim.ids()[i]);
  }
  return s;
}

// Phase 1's scene: restored from the checkpoint, or built (from a settled start when the
// case names an earlier run's last state).
dem::scene::CentrecScene set_up(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                                const io::RunCheckpoint* ck) {
  io::ensure_directory(out_dir);
  std::fprintf(stderr, "centrec dem: %s\nset-up: %s\n", cf.path.c_str(),
               ck ? ("restoring the checkpoint in " + out_dir).c_str()
                  : "building the drum, its rough wall and the initial film");
  dem::scene::SceneConfig start = dc.scene;
  if (!ck && !dc.initial_film_from_run.empty()) {
    start.initial_film = settled_start(cf, dc);
    std::fprintf(stderr, "  settled start: %zu free particles from the last state of %s, %zu contacts kept (%zu with walls)\n",
                 start.initial_film.settled.size(), dc.initial_film_from_run.c_str(),
                 start.initial_film.settled_contacts.size(), start.initial_film.settled_wall_contacts.size());
  }
  return ck ? dem::scene::CentrecScene(dc.scene, ck->scene) : dem::scene::CentrecScene(start);
}
}  // namespace

const char* DemRun::name(Phase p) {
  switch (p) {
    case Phase::spin_up:
      return "spin-up";
    case Phase::sampling:
      return "sampling";
    case Phase::done:
      break;
  }
  return "done";
}

DemRun::Phase DemRun::phase_named(const std::string& name) {
  for (const Phase p : {Phase::spin_up, Phase::sampling, Phase::done})
    if (name == DemRun::name(p)) return p;
  throw std::runtime_error("checkpoint: unknown run phase '" + name + "' (spin-up, sampling or done)");
}

DemRun::DemRun(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
               const std::optional<io::RunCheckpoint>& ck)
    : cf_(cf),
      dc_(dc),
      out_dir_(out_dir),
      ck_(ck ? &*ck : nullptr),
      scene_(set_up(cf, dc, out_dir, ck_)),
      sim_(scene_.simulation()),
      engine_at_start_(sim_.times()),
      scene_at_start_(scene_.times()),
      rebuilds_at_start_(sim_.neighbour_stats().rebuilds),
      edits_at_start_(sim_.neighbour_stats().list_edits),
      period_(scene_.turn_period()),
      chunk_(std::max(sim_.dt() * scene_.steps_per_batch(), std::min(0.01, dc.run.duration))),
      steps_before_(ck ? ck->particle_steps : 0.0),
      wall_before_(ck ? ck->wall_time : 0.0),
      progress_(dc.run.duration + dc.sampling.turns * period_, dc.run.progress_interval, sim_.time()),
      sampler_(scene_, dc.sampling.sampler),
      tracks_(dc.scene.feeder.enabled && !dc.scene.slice.enabled),
      sampled_(ck ? ck->sampled_turns : 0),
      in_turn_(ck ? ck->turn_snapshots : 0),
      checkpoint_at_(std::chrono::steady_clock::now()) {
  std::fprintf(stderr, "%s  %s\n  %s\n  %lld glued + %lld free particles, %d thread(s)\n",
               ck ? ("  resumed at t = " + std::to_string(sim_.time()) + " s (" + ck->phase + ")\n").c_str() : "",
               sim_.time_step_advice().report().c_str(), config::time_step_statement(sim_.time_step_advice(), dc.scene.dt).c_str(),
               static_cast<long long>(scene_.glued_particles()), static_cast<long long>(scene_.free_particles()),
               sim_.threads());
  if (ck_) phase_named(ck_->phase);
}

io::DemRunResult DemRun::run() {
  if (!ck_ || phase_named(ck_->phase) == Phase::spin_up) spin_up();
  start_sampling();
  while (sampled_ < turns_) {
    sample_turn();
    ++sampled_;
    fixed_point(Phase::sampling);
  }
  return done();
}

template <class Body>
void DemRun::advance(Body&& body) {
  const std::int64_t s0 = sim_.step_count();
  const double n0 = static_cast<double>(sim_.size()), f0 = static_cast<double>(scene_.free_particles());
  body();
  const double steps = static_cast<double>(sim_.step_count() - s0);
  particle_steps_ += 0.5 * (n0 + static_cast<double>(sim_.size())) * steps;
  moving_steps_ += 0.5 * (f0 + static_cast<double>(scene_.free_particles())) * steps;
  progress_.update(sim_.time(), sim_.time() / period_, particle_steps_, false, [this] { return flows(); });
}

void DemRun::fixed_point(Phase phase) {
  sim_.rebuild_lists();
  checkpoint(phase, false);
  if (const int signal = InterruptGuard::received()) {
    checkpoint(phase, true);
    throw RunInterrupted(signal, sim_.time(), out_dir_);
  }
}

void DemRun::checkpoint(Phase phase, bool force) {
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - checkpoint_at_).count();
  if (!force && !(dc_.run.checkpoint_interval > 0.0 && since >= dc_.run.checkpoint_interval)) return;
  const auto t0 = std::chrono::steady_clock::now();
  io::RunCheckpoint c;
  c.code_version = centrec::io::code_version();
  c.case_path = cf_.path;
  c.resolved_yaml = cf_.resolved_yaml;
  c.phase = name(phase);
  c.sampled_turns = sampled_;
  c.turn_snapshots = in_turn_;
  c.particle_steps = steps_before_ + particle_steps_;
  c.wall_time = wall_before_ + progress_.elapsed();
  c.scene = scene_.export_state();
  if (phase != Phase::spin_up) {
    flush_tracks();  // before the checkpoint that counts them
    c.sampler["state"] = sampler_.save();
    c.start_snapshot = snapshots_.front().data;
  }
  io::write_checkpoint(out_dir_, c);
  checkpoint_at_ = std::chrono::steady_clock::now();
  checkpoint_seconds_ += std::chrono::duration<double>(checkpoint_at_ - t0).count();
}

std::string DemRun::flows() const {
  // A drum's outlet and inlet, a slice's axial flow (and its controller's target) and free particles.
  const auto w = dem::scene::window_flows(scene_.mass_flow_log(), period_);
  const double target = dc_.scene.slice.target_mass_flow;
  char b[128];
  if (dc_.scene.slice.enabled && target > 0.0)
    std::snprintf(b, sizeof b, "slice flow %.2f g/s (target %.2f), %zu particles", w.axial * 1e3, target * 1e3,
                  sim_.size());
  else if (dc_.scene.slice.enabled)
    std::snprintf(b, sizeof b, "slice flow %.2f g/s", w.axial * 1e3);
  else
    std::snprintf(b, sizeof b, "outlet %.2f g/s, inlet %.2f g/s", w.out * 1e3, w.fed * 1e3);
  return b;
}

double DemRun::engine_seconds() const {
  const dem::EngineTimes& e = sim_.times();
  const dem::scene::SceneTimes& t = scene_.times();
  return e.force_pass + e.first_half + e.neighbour_build + e.list_edit + t.insertion + t.outlet + t.bookkeeping;
}

void DemRun::keep(const dem::scene::SnapshotArrays& s, bool with_glued) {
  char name[32];
  std::snprintf(name, sizeof name, "t%.6f", s.time);
  snapshots_.push_back({name, s, with_glued ? glued_layer(sim_) : dem::scene::SnapshotArrays{}});
}

void DemRun::flush_tracks() {
  io::write_track_part(out_dir_, track_first_, tracks_pending_);
  track_first_ += static_cast<std::int64_t>(tracks_pending_.size());
  tracks_pending_.clear();
}

void DemRun::spin_up() {
  // What the run will simulate, stated up front: run.duration is the shortest spin-up, not a
  // limit on the whole run (docs/running.md).
  char what[400];
  std::snprintf(what, sizeof what,
                "the drum runs to t = %.4g s (dem.run.duration) so the film fills and its outflow settles, on until "
                "steady for at most %.4g s more (dem.run.max_extension), then %.4g sampled turns (%.4g s): %.4g-%.4g s "
                "in all",
                dc_.run.duration, dc_.run.extension_cap(), dc_.sampling.turns, dc_.sampling.turns * period_,
                dc_.run.duration + dc_.sampling.turns * period_,
                dc_.run.duration + dc_.run.extension_cap() + dc_.sampling.turns * period_);
  progress_.phase(name(Phase::spin_up), what);
  // An underfed drum never reaches the state asked: stop after its first turn, not hours later.
  const bool fed = dc_.scene.feeder.enabled && !dc_.scene.slice.enabled && dc_.scene.feeder.mass_flow > 0.0;
  bool feeder_checked = !fed || sim_.time() >= period_;
  while (sim_.time() < dc_.run.duration - 0.5 * sim_.dt()) {
    advance([&] { scene_.advance(std::min(chunk_, dc_.run.duration - sim_.time())); });
    if (!feeder_checked && sim_.time() >= period_) {
      feeder_checked = true;
      const std::string why = dem::scene::feeder_shortfall(dc_.scene, scene_.feeder_stats(), sim_.time());
      if (!why.empty()) throw config::ConfigError(cf_.path + ": " + why);
    }
    fixed_point(Phase::spin_up);
  }
  // Past run.duration, chunk by chunk until the flow is steady over the flow window or
  // run.max_extension (default: run.duration) more has passed; the run report then says
  // whether it was steady.
  const double window = dc_.run.flow_window_turns * period_, cap = dc_.run.duration + dc_.run.extension_cap();
  auto steadiness = [&] {
    return dem::scene::flow_steadiness(scene_.mass_flow_log(), dc_.scene, window, dc_.run.steady_tolerance);
  };
  bool told = false;
  for (auto st = steadiness(); sim_.time() < cap - 0.5 * sim_.dt() && !st.steady; st = steadiness()) {
    if (!told) {
      std::fprintf(stderr, "  not steady at t = %.4g s (%s): spin-up extended, up to t = %.4g s\n", sim_.time(),
                   st.describe().c_str(), cap);
      progress_.set_total(cap + dc_.sampling.turns * period_, sim_.time());
    }
    told = true;
    advance([&] { scene_.advance(std::min(chunk_, cap - sim_.time())); });
    fixed_point(Phase::spin_up);
  }
  if (told) std::fprintf(stderr, "  spin-up ended at t = %.4g s: %s\n", sim_.time(), steadiness().describe().c_str());
}

void DemRun::start_sampling() {
  // Every snapshot the samplers see is kept for dem.h5 and dem.xmf, with the glued layer
  // (a resumed run keeps those after its checkpoint and the start snapshot, without glued).
  if (ck_ && phase_named(ck_->phase) != Phase::spin_up) {
    sampler_.load(ck_->sampler.at("state"));
    keep(ck_->start_snapshot.value(), false);
  } else {
    keep(dem::scene::take_snapshot(sim_), true);  // the film as sampling starts
  }
  turns_ = static_cast<int>(std::floor(dc_.sampling.turns + 1e-9));
  per_turn_ = sampler_.spec().snapshots_per_turn;
  stride_ = io::snapshot_stride(turns_ * per_turn_, static_cast<double>(sim_.size()));
  taken_ = sampled_ * per_turn_ + in_turn_;  // sampled snapshots so far, counted from the start of sampling
  if (tracks_) {  // parts past the checkpoint resumed from are taken again
    io::drop_track_parts_from(out_dir_, taken_);
    track_first_ = taken_;
  }
  // The run ends when the snapshots still to take are taken, from wherever the sampling
  // starts or resumes (after an extended spin-up, inside a turn).
  const int to_take = std::max(0, turns_ * per_turn_ - taken_);
  progress_.set_total(sim_.time() + (per_turn_ > 0 ? to_take * (period_ / per_turn_) : 0.0), sim_.time());
  if (sampled_ < turns_)
    progress_.phase(name(Phase::sampling), std::to_string(turns_) + " turn(s) of " + std::to_string(per_turn_) +
                                               " snapshots each for the film fields (thickness, velocity profiles, "
                                               "solid fraction)");
}

void DemRun::sample_turn() {
  // One turn as SceneSampler::sample_turns does it (from the snapshot a resumed run stopped
  // at; each interval with the dispersion's burst of position samples), keeping every
  // stride-th snapshot; between snapshots, a fixed point as in the spin-up.
  const auto t0 = std::chrono::steady_clock::now();
  const double engine0 = engine_seconds(), checkpoints0 = checkpoint_seconds_;
  for (; in_turn_ < per_turn_;) {
    advance([&] { sampler_.advance_interval(scene_); });
    dem::scene::SnapshotArrays s = dem::scene::take_snapshot(sim_);
    if (tracks_) tracks_pending_.push_back(film::track_snapshot(s));
    if (++taken_ % stride_ == 0) keep(s, true);
    sampler_.add_snapshot(std::move(s));
    if (++in_turn_ == per_turn_) break;  // the turn's end is the caller's fixed point
    fixed_point(Phase::sampling);
  }
  sampler_.end_turn();
  in_turn_ = 0;
  sampling_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
                       (engine_seconds() - engine0) - (checkpoint_seconds_ - checkpoints0);
}

io::DemRunResult DemRun::done() {
  flush_tracks();
  if (sim_.time() > snapshots_.back().data.time) keep(dem::scene::take_snapshot(sim_), true);
  progress_.update(sim_.time(), sim_.time() / period_, particle_steps_, true, [this] { return flows(); });
  progress_.finish();
  checkpoint(Phase::done, dc_.run.checkpoint_interval > 0.0);
  const double particle_steps = steps_before_ + particle_steps_;
  const double wall = wall_before_ + progress_.elapsed();

  io::DemRunResult r;
  r.engine = "centrec";
  r.engine_version = centrec::io::code_version();
  r.threads = sim_.threads();
  r.simulated_time = sim_.time();
  r.dt = sim_.dt();
  r.steps = sim_.step_count();
  r.free_particles = scene_.free_particles();
  r.glued_particles = scene_.glued_particles();
  r.holdup_kg = scene_.holdup_mass();
  r.mass_flow = scene_.mass_flow_log();
  r.controller = scene_.controller_log();
  r.feeder_deferred = scene_.feeder_stats().deferred;
  r.contacts_per_particle = sim_.neighbour_stats().contacts_per_particle();
  r.particle_steps = particle_steps;
  r.moving_particle_steps = ck_ ? -1.0 : moving_steps_;  // a checkpoint does not carry the count
  r.wall_time = wall;
  r.neighbour_rebuilds = static_cast<std::int64_t>(sim_.neighbour_stats().rebuilds - rebuilds_at_start_);
  r.list_edits = static_cast<std::int64_t>(sim_.neighbour_stats().list_edits - edits_at_start_);
  r.pair_pass_idle = sim_.times().pair_pass_idle - engine_at_start_.pair_pass_idle;
  r.parked_pass_idle = sim_.times().parked_pass_idle - engine_at_start_.parked_pass_idle;
  if (!ck_) {  // a resumed run's timers start at its resumption
    const dem::EngineTimes& e = sim_.times();
    const dem::EngineTimes& e0 = engine_at_start_;
    const dem::scene::SceneTimes& t = scene_.times();
    const dem::scene::SceneTimes& t0 = scene_at_start_;
    r.phase_seconds = {{"force_pass", e.force_pass - e0.force_pass},
                       {"first_half", e.first_half - e0.first_half},
                       {"neighbour_build", e.neighbour_build - e0.neighbour_build},
                       {"list_edit", e.list_edit - e0.list_edit},
                       {"insertion", t.insertion - t0.insertion},
                       {"outlet", t.outlet - t0.outlet},
                       {"bookkeeping", t.bookkeeping - t0.bookkeeping},
                       {"sampling", sampling_seconds_},
                       {"checkpoints", checkpoint_seconds_}};
    double timed = 0.0;
    for (const auto& p : r.phase_seconds) timed += p.second;
    r.phase_seconds.push_back({"other", wall - timed});
  }
  r.fields = sampler_.fields();
  r.snapshots = std::move(snapshots_);
  r.snapshot_stride = stride_;
  return r;
}

}  // namespace centrec::runs
