// The native DEM run of a case: spin-up, sampled turns, checkpoints, then the shared outputs.
#include "runs/dem_case_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/feeder.hpp"
#include "dem/scene/mass_flow_window.hpp"
#include "dem/scene/scene_sampler.hpp"
#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
#include "config/case_checks.hpp"
#include "config/strict_yaml.hpp"
#include "runs/dem_run_report.hpp"
#include "runs/interrupt.hpp"
#include "runs/progress_meter.hpp"
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
}  // namespace

io::DemRunResult run_dem_natively(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                                  const std::optional<io::RunCheckpoint>& ck) {
  io::ensure_directory(out_dir);

  std::fprintf(stderr, "centrec dem: %s\nset-up: %s\n", cf.path.c_str(),
               ck ? ("restoring the checkpoint in " + out_dir).c_str()
                  : "building the drum, its rough wall and the initial film");
  dem::scene::SceneConfig start = dc.scene;
  if (!ck && !dc.initial_film_from_run.empty()) {
    start.initial_film.settled = settled_start(cf, dc);
    std::fprintf(stderr, "  settled start: %zu free particles from the last state of %s\n",
                 start.initial_film.settled.size(), dc.initial_film_from_run.c_str());
  }
  dem::scene::CentrecScene scene = ck ? dem::scene::CentrecScene(dc.scene, ck->scene) : dem::scene::CentrecScene(start);
  auto& sim = scene.simulation();
  std::fprintf(stderr, "%s  %s\n  %s\n  %lld glued + %lld free particles, %d thread(s)\n",
               ck ? ("  resumed at t = " + std::to_string(sim.time()) + " s (" + ck->phase + ")\n").c_str() : "",
               sim.time_step_advice().report().c_str(),
               config::time_step_statement(sim.time_step_advice(), dc.scene.dt).c_str(),
               static_cast<long long>(scene.glued_particles()), static_cast<long long>(scene.free_particles()),
               sim.threads());

  // The phase timers from here (the set-up's own list build and forces are not the run's).
  const dem::EngineTimes engine_at_start = sim.times();
  const dem::scene::SceneTimes scene_at_start = scene.times();
  const std::size_t rebuilds_at_start = sim.neighbour_stats().rebuilds, edits_at_start = sim.neighbour_stats().list_edits;
  const double period = scene.turn_period();
  const double total = dc.run.duration + dc.sampling.turns * period;
  ProgressMeter progress(total, dc.run.progress_interval);
  const double chunk = std::max(sim.dt() * scene.steps_per_batch(), std::min(0.01, dc.run.duration));
  const double steps_before = ck ? ck->particle_steps : 0.0, wall_before = ck ? ck->wall_time : 0.0;
  double particle_steps = 0.0, moving_steps = 0.0;  // this process's (all particles, free ones)
  double sampling_seconds = 0.0, checkpoint_seconds = 0.0;  // the samplers' own work, checkpoint writes
  // Progress lines carry the flow over the last turn: a drum's outlet and inlet, a slice's
  // axial flow (and its controller's target) and free particles.
  const bool slice = dc.scene.slice.enabled;
  const double target = dc.scene.slice.target_mass_flow;
  auto flows = [&] {
    const auto w = dem::scene::window_flows(scene.mass_flow_log(), period);
    char b[128];
    if (slice && target > 0.0)
      std::snprintf(b, sizeof b, "slice flow %.2f g/s (target %.2f), %zu particles", w.axial * 1e3, target * 1e3,
                    sim.size());
    else if (slice)
      std::snprintf(b, sizeof b, "slice flow %.2f g/s", w.axial * 1e3);
    else
      std::snprintf(b, sizeof b, "outlet %.2f g/s, inlet %.2f g/s", w.out * 1e3, w.fed * 1e3);
    return std::string(b);
  };
  // The engine's and the scene's phase timers together (what the samplers' time excludes).
  auto engine_seconds = [&] {
    const dem::EngineTimes& e = sim.times();
    const dem::scene::SceneTimes& t = scene.times();
    return e.force_pass + e.first_half + e.neighbour_build + e.list_edit + t.insertion + t.outlet + t.bookkeeping;
  };
  auto advance = [&](auto&& body) {
    const std::int64_t s0 = sim.step_count();
    const double n0 = static_cast<double>(sim.size()), f0 = static_cast<double>(scene.free_particles());
    body();
    const double steps = static_cast<double>(sim.step_count() - s0);
    particle_steps += 0.5 * (n0 + static_cast<double>(sim.size())) * steps;
    moving_steps += 0.5 * (f0 + static_cast<double>(scene.free_particles())) * steps;
    progress.update(sim.time(), sim.time() / period, particle_steps, false, flows);
  };

  // Checkpoints. The run rebuilds the neighbour lists at fixed points (after every spin-up
  // chunk and every sampled snapshot) and checkpoints only there, so whether and when a
  // checkpoint is written (wall clock) never changes the result, and a resumed run
  // continues bitwise (Simulation::rebuild_lists). A checkpoint inside a sampled turn keeps
  // the samplers' partial turn, so a stop loses at most one snapshot interval of simulated
  // time beyond checkpoint_interval (docs/reliability.md).
  dem::scene::SceneSampler sampler(scene, dc.sampling.sampler);
  std::vector<io::NamedSnapshot> snapshots;
  int sampled = ck ? ck->sampled_turns : 0;
  int in_turn = ck ? ck->turn_snapshots : 0;  // snapshots taken into the unfinished turn
  auto checkpoint_at = std::chrono::steady_clock::now();
  auto checkpoint = [&](const std::string& phase, bool force) {
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - checkpoint_at).count();
    if (!force && !(dc.run.checkpoint_interval > 0.0 && since >= dc.run.checkpoint_interval)) return;
    const auto t0 = std::chrono::steady_clock::now();
    io::RunCheckpoint c;
    c.code_version = centrec::io::code_version();
    c.case_path = cf.path;
    c.resolved_yaml = cf.resolved_yaml;
    c.phase = phase;
    c.sampled_turns = sampled;
    c.turn_snapshots = in_turn;
    c.particle_steps = steps_before + particle_steps;
    c.wall_time = wall_before + progress.elapsed();
    c.scene = scene.export_state();
    if (phase != "spin-up") {
      c.sampler["state"] = sampler.save();
      c.start_snapshot = snapshots.front().data;
    }
    io::write_checkpoint(out_dir, c);
    checkpoint_at = std::chrono::steady_clock::now();
    checkpoint_seconds += std::chrono::duration<double>(checkpoint_at - t0).count();
  };
  // Ctrl-C / SIGTERM: checkpoint at the next safe point (where the periodic ones are written) and stop.
  const InterruptGuard interrupt;
  auto stop_if_interrupted = [&](const std::string& phase) {
    if (const int signal = InterruptGuard::received()) {
      checkpoint(phase, true);
      throw RunInterrupted(signal, sim.time(), out_dir);
    }
  };

  // Spin-up (filling, reaching steady state), then sampling turn by turn.
  // Past run.duration the spin-up goes on, chunk by chunk, until the flow is steady over the
  // flow window (dem/scene/mass_flow_window.hpp) or run.max_extension (default: run.duration)
  // more has passed; the run report then says whether it was steady.
  const double window = dc.run.flow_window_turns * period, cap = dc.run.duration + dc.run.extension_cap();
  auto steadiness = [&] {
    return dem::scene::flow_steadiness(scene.mass_flow_log(), dc.scene, window, dc.run.steady_tolerance);
  };
  if (!ck || ck->phase == "spin-up") {
    char what[128];
    std::snprintf(what, sizeof what, "the drum runs to t = %.4g s (dem.run.duration) so the film fills and its outflow settles",
                  dc.run.duration);
    progress.phase("spin-up", what);
    // An underfed drum never reaches the state asked: stop after its first turn, not hours later.
    const bool fed = dc.scene.feeder.enabled && !slice && dc.scene.feeder.mass_flow > 0.0;
    bool feeder_checked = !fed || sim.time() >= period;
    while (sim.time() < dc.run.duration - 0.5 * sim.dt()) {
      advance([&] { scene.advance(std::min(chunk, dc.run.duration - sim.time())); });
      if (!feeder_checked && sim.time() >= period) {
        feeder_checked = true;
        const std::string why = dem::scene::feeder_shortfall(dc.scene, scene.feeder_stats(), sim.time());
        if (!why.empty()) throw config::ConfigError(cf.path + ": " + why);
      }
      sim.rebuild_lists();
      checkpoint("spin-up", false);
      stop_if_interrupted("spin-up");
    }
    bool told = false;
    for (auto st = steadiness(); sim.time() < cap - 0.5 * sim.dt() && !st.steady; st = steadiness()) {
      if (!told) {
        std::fprintf(stderr, "  not steady at t = %.4g s (%s): spin-up extended, up to t = %.4g s\n", sim.time(),
                     st.describe().c_str(), cap);
        progress.set_total(cap + dc.sampling.turns * period, sim.time());
      }
      told = true;
      advance([&] { scene.advance(std::min(chunk, cap - sim.time())); });
      sim.rebuild_lists();
      checkpoint("spin-up", false);
      stop_if_interrupted("spin-up");
    }
    if (told) {
      std::fprintf(stderr, "  spin-up ended at t = %.4g s: %s\n", sim.time(), steadiness().describe().c_str());
      progress.set_total(sim.time() + dc.sampling.turns * period, sim.time());
    }
  }
  // Every snapshot the samplers see is kept for dem.h5 and dem.xmf, with the glued layer
  // (a resumed run keeps those after its checkpoint and the start snapshot, without glued).
  auto keep = [&](const dem::scene::SnapshotArrays& s, bool with_glued) {
    char name[32];
    std::snprintf(name, sizeof name, "t%.6f", s.time);
    snapshots.push_back({name, s, with_glued ? glued_layer(sim) : dem::scene::SnapshotArrays{}});
  };
  if (ck && ck->phase != "spin-up") {
    sampler.load(ck->sampler.at("state"));
    keep(ck->start_snapshot.value(), false);
  } else {
    keep(dem::scene::take_snapshot(sim), true);  // the film as sampling starts
  }
  const int turns = static_cast<int>(std::floor(dc.sampling.turns + 1e-9));
  const int per_turn = sampler.spec().snapshots_per_turn;
  const int stride = io::snapshot_stride(turns * per_turn, static_cast<double>(sim.size()));
  int taken = sampled * per_turn + in_turn;  // sampled snapshots so far, counted from the start of sampling
  // One turn as SceneSampler::sample_turns does it (from the snapshot a resumed run stopped
  // at; each interval with the dispersion's burst of position samples), keeping every
  // stride-th snapshot; between snapshots, a fixed point as in the spin-up.
  auto sample_turn = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    const double engine0 = engine_seconds(), checkpoints0 = checkpoint_seconds;
    for (; in_turn < per_turn;) {
      advance([&] { sampler.advance_interval(scene); });
      dem::scene::SnapshotArrays s = dem::scene::take_snapshot(sim);
      if (++taken % stride == 0) keep(s, true);
      sampler.add_snapshot(std::move(s));
      if (++in_turn == per_turn) break;  // the turn's end is the fixed point below
      sim.rebuild_lists();
      checkpoint("sampling", false);
      stop_if_interrupted("sampling");
    }
    sampler.end_turn();
    in_turn = 0;
    sampling_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
                        (engine_seconds() - engine0) - (checkpoint_seconds - checkpoints0);
  };
  if (sampled < turns)
    progress.phase("sampling", std::to_string(turns) + " turn(s) of " + std::to_string(per_turn) +
                                   " snapshots each for the film fields (thickness, velocity profiles, solid fraction)");
  while (sampled < turns) {
    sample_turn();
    ++sampled;
    sim.rebuild_lists();
    checkpoint("sampling", false);
    stop_if_interrupted("sampling");
  }
  if (sim.time() > snapshots.back().data.time) keep(dem::scene::take_snapshot(sim), true);
  progress.update(sim.time(), sim.time() / period, particle_steps, true, flows);
  progress.finish();
  checkpoint("done", dc.run.checkpoint_interval > 0.0);
  particle_steps += steps_before;
  const double wall = wall_before + progress.elapsed();

  io::DemRunResult r;
  r.engine = "centrec";
  r.engine_version = centrec::io::code_version();
  r.threads = sim.threads();
  r.simulated_time = sim.time();
  r.dt = sim.dt();
  r.steps = sim.step_count();
  r.free_particles = scene.free_particles();
  r.glued_particles = scene.glued_particles();
  r.holdup_kg = scene.holdup_mass();
  r.mass_flow = scene.mass_flow_log();
  r.controller = scene.controller_log();
  r.feeder_deferred = scene.feeder_stats().deferred;
  r.contacts_per_particle = sim.neighbour_stats().contacts_per_particle();
  r.particle_steps = particle_steps;
  r.moving_particle_steps = ck ? -1.0 : moving_steps;  // a checkpoint does not carry the count
  r.wall_time = wall;
  r.neighbour_rebuilds = static_cast<std::int64_t>(sim.neighbour_stats().rebuilds - rebuilds_at_start);
  r.list_edits = static_cast<std::int64_t>(sim.neighbour_stats().list_edits - edits_at_start);
  r.pair_pass_idle = sim.times().pair_pass_idle - engine_at_start.pair_pass_idle;
  r.parked_pass_idle = sim.times().parked_pass_idle - engine_at_start.parked_pass_idle;
  if (!ck) {  // a resumed run's timers start at its resumption
    const dem::EngineTimes& e = sim.times();
    const dem::EngineTimes& e0 = engine_at_start;
    const dem::scene::SceneTimes& t = scene.times();
    const dem::scene::SceneTimes& t0 = scene_at_start;
    r.phase_seconds = {{"force_pass", e.force_pass - e0.force_pass},
                       {"first_half", e.first_half - e0.first_half},
                       {"neighbour_build", e.neighbour_build - e0.neighbour_build},
                       {"list_edit", e.list_edit - e0.list_edit},
                       {"insertion", t.insertion - t0.insertion},
                       {"outlet", t.outlet - t0.outlet},
                       {"bookkeeping", t.bookkeeping - t0.bookkeeping},
                       {"sampling", sampling_seconds},
                       {"checkpoints", checkpoint_seconds}};
    double timed = 0.0;
    for (const auto& p : r.phase_seconds) timed += p.second;
    r.phase_seconds.push_back({"other", wall - timed});
  }
  r.fields = sampler.fields();
  r.snapshots = std::move(snapshots);
  r.snapshot_stride = stride;
  return r;
}

DemEngine native_engine(const std::optional<io::RunCheckpoint>& ck) {
  return [ck](const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir) {
    return run_dem_natively(cf, dc, out_dir, ck);
  };
}

io::DemRunResult run_dem_case(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                              const DemEngine& engine) {
  io::ensure_directory(out_dir);
  io::DemRunResult r = engine(cf, dc, out_dir);
  write_dem_run_report(out_dir, cf, dc, r);
  return r;
}

}  // namespace centrec::runs
