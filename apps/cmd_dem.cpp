// `centrec dem CASE.yaml --out DIR`: a DEM-only run of the CentRec scene.
#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>
#include <stdexcept>

#include "atomic_write.hpp"
#include "case_file.hpp"
#include "checkpoint_h5.hpp"
#include "code_version.hpp"
#include "commands.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_sampler.hpp"
#include "dem_case_run.hpp"
#include "dem_engine_options.hpp"
#include "dem_liggghts_run.hpp"
#include "dem_run_report.hpp"
#include "progress_meter.hpp"

namespace centrec::cli {

namespace {

struct DemOptions {
  std::string case_path, out_dir = "out/dem", resume_dir;
  int threads = -1;         // -1 = from the case
  double duration = -1.0;   // -1 = from the case
  DemEngineOptions engine;
};

void print_dem_help() {
  std::printf(
      "usage: centrec dem CASE.yaml [--out DIR] [--threads N] [--duration SECONDS]\n"
      "                  [--engine centrec|liggghts] [--ranks N] [--mpirun CMD] [--liggghts EXE]\n"
      "                  [--wall-rolling-model relative|liggghts]\n"
      "       centrec dem --resume DIR [--threads N]\n\n"
      "Runs the DEM of the CentRec drum (or periodic slice) described by the case's\n"
      "`dem:` section and writes DIR/summary.json (headline figures and the resolved\n"
      "configuration), DIR/dem.h5 (mass flows, averaged film fields, particle snapshots;\n"
      "units as attributes), DIR/dem.xmf (open in ParaView) and DIR/mass_flow.csv.\n"
      "--threads and --duration override run.threads and run.duration.\n"
      "--engine liggghts runs the same case on LIGGGHTS 3.8 (`mpirun -np N liggghts`, N = --ranks;\n"
      "--mpirun srun for a cluster launcher) in DIR/liggghts and reads its dumps into the same\n"
      "samplers and outputs; settings LIGGGHTS cannot express are refused (see export-liggghts).\n"
      "--wall-rolling-model overrides contacts.wall_rolling_model (liggghts: LIGGGHTS' form).\n\n"
      "Every run.checkpoint_interval seconds of wall time (default 300; 0 = off) and at the\n"
      "end the run writes DIR/checkpoint.h5 (atomically). --resume DIR continues a killed\n"
      "run from it with the case stored there (a CASE.yaml given too must match it); the\n"
      "result is bitwise the same as the uninterrupted run's. A killed sampling turn is\n"
      "sampled again from its start.\n");
}

DemOptions parse(const Args& args) {
  DemOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(name) + " needs a value");
      return args[++i];
    };
    if (parse_engine_option(args, i, o.engine)) continue;
    if (a == "--out") o.out_dir = value("--out");
    else if (a == "--resume") o.resume_dir = value("--resume");
    else if (a == "--threads") o.threads = std::stoi(value("--threads"));
    else if (a == "--duration") o.duration = std::stod(value("--duration"));
    else if (!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
    else if (o.case_path.empty()) o.case_path = a;
    else throw std::invalid_argument("more than one case file given");
  }
  if (!o.resume_dir.empty()) {
    if (o.engine.engine != "centrec") throw std::invalid_argument("--resume is for the native engine (centrec) only");
    if (o.duration > 0.0) throw std::invalid_argument("--duration cannot change a resumed run (it is in the checkpoint's case)");
    o.out_dir = o.resume_dir;
  }
  if (o.case_path.empty() && o.resume_dir.empty())
    throw std::invalid_argument("no case file given (centrec dem --help)");
  return o;
}

// The LIGGGHTS engine: same case, same samplers and outputs (dem_liggghts_run).
int run_on_liggghts(const CaseFile& cf, const DemCase& dc, const DemOptions& opt) {
  LiggghtsLaunch launch;
  launch.ranks = opt.engine.ranks;
  launch.mpirun = opt.engine.mpirun;
  launch.liggghts = opt.engine.liggghts;
  const DemRunResult r = run_dem_on_liggghts(cf, dc, opt.out_dir, launch);
  write_dem_run_report(opt.out_dir, cf, dc, r);
  return 0;
}

}  // namespace

int cmd_dem(const Args& args) {
  if (wants_help(args)) {
    print_dem_help();
    return 0;
  }
  const DemOptions opt = parse(args);
  // A resumed run takes its case from the checkpoint (a case file given too must match).
  std::optional<RunCheckpoint> ck;
  if (!opt.resume_dir.empty()) ck = read_checkpoint(opt.resume_dir);
  const CaseFile cf = ck ? read_case_text(ck->resolved_yaml, ck->case_path) : read_case_file(opt.case_path);
  if (ck && !opt.case_path.empty() && read_case_file(opt.case_path).resolved_yaml != ck->resolved_yaml)
    throw std::invalid_argument(opt.case_path + " does not match the case stored in " + checkpoint_path(opt.resume_dir) +
                                "; resume without the case file, or start a new run");
  if (ck && ck->code_version != centrec::code_version())
    std::fprintf(stderr, "centrec dem: warning: checkpoint written by %s, resuming with %s\n", ck->code_version.c_str(),
                 centrec::code_version());
  if (!cf.dem) throw std::invalid_argument(cf.path + " has no `dem:` section");
  DemCase dc = *cf.dem;
  if (opt.threads >= 0) dc.scene.threads = opt.threads;
  if (opt.duration > 0.0) dc.run.duration = opt.duration;
  if (!opt.engine.wall_rolling_model.empty()) apply_wall_rolling_model(dc, opt.engine.wall_rolling_model);
  if (opt.engine.engine == "liggghts") {
    ensure_directory(opt.out_dir);
    return run_on_liggghts(cf, dc, opt);
  }
  run_dem_case(cf, dc, opt.out_dir, ck);
  return 0;
}

void run_dem_case(const CaseFile& cf, const DemCase& dc, const std::string& out_dir,
                  const std::optional<RunCheckpoint>& ck) {
  ensure_directory(out_dir);

  dem::scene::CentrecScene scene = ck ? dem::scene::CentrecScene(dc.scene, ck->scene) : dem::scene::CentrecScene(dc.scene);
  auto& sim = scene.simulation();
  std::fprintf(stderr, "centrec dem: %s%s\n  %s\n  dt = %.3g s, %lld glued + %lld free particles, %d thread(s)\n",
               cf.path.c_str(), ck ? (" resumed at t = " + std::to_string(sim.time()) + " s (" + ck->phase + ")").c_str() : "",
               sim.time_step_advice().report().c_str(), sim.dt(), static_cast<long long>(scene.glued_particles()),
               static_cast<long long>(scene.free_particles()), sim.threads());

  const double period = scene.turn_period();
  const double total = dc.run.duration + dc.sampling.turns * period;
  ProgressMeter progress(total, dc.run.progress_interval);
  const double chunk = std::max(sim.dt() * scene.steps_per_batch(), std::min(0.01, dc.run.duration));
  const double steps_before = ck ? ck->particle_steps : 0.0, wall_before = ck ? ck->wall_time : 0.0;
  double particle_steps = 0.0;  // this process's
  auto advance = [&](auto&& body) {
    const std::int64_t s0 = sim.step_count();
    const double n0 = static_cast<double>(sim.size());
    body();
    particle_steps += 0.5 * (n0 + static_cast<double>(sim.size())) * static_cast<double>(sim.step_count() - s0);
    progress.update(sim.time(), sim.time() / period, particle_steps);
  };

  // Checkpoints. The run rebuilds the neighbour lists at fixed points (after every spin-up
  // chunk and every sampled turn) and checkpoints only there, so whether and when a
  // checkpoint is written (wall clock) never changes the result, and a resumed run
  // continues bitwise (Simulation::rebuild_lists).
  dem::scene::SceneSampler sampler(scene, dc.sampling.sampler);
  std::vector<NamedSnapshot> snapshots;
  int sampled = ck ? ck->sampled_turns : 0;
  auto checkpoint_at = std::chrono::steady_clock::now();
  auto checkpoint = [&](const std::string& phase, bool force) {
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - checkpoint_at).count();
    if (!force && !(dc.run.checkpoint_interval > 0.0 && since >= dc.run.checkpoint_interval)) return;
    RunCheckpoint c;
    c.code_version = centrec::code_version();
    c.case_path = cf.path;
    c.resolved_yaml = cf.resolved_yaml;
    c.phase = phase;
    c.sampled_turns = sampled;
    c.particle_steps = steps_before + particle_steps;
    c.wall_time = wall_before + progress.elapsed();
    c.scene = scene.export_state();
    if (phase != "spin-up") {
      c.sampler["state"] = sampler.save();
      c.start_snapshot = snapshots.front().data;
    }
    write_checkpoint(out_dir, c);
    checkpoint_at = std::chrono::steady_clock::now();
  };

  // Spin-up (filling, reaching steady state), then sampling turn by turn.
  if (!ck || ck->phase == "spin-up") {
    while (sim.time() < dc.run.duration - 0.5 * sim.dt()) {
      advance([&] { scene.advance(std::min(chunk, dc.run.duration - sim.time())); });
      sim.rebuild_lists();
      checkpoint("spin-up", false);
    }
  }
  auto keep = [&](dem::scene::SnapshotArrays s) {
    char name[32];
    std::snprintf(name, sizeof name, "t%.6f", s.time);
    snapshots.push_back({name, std::move(s)});
  };
  auto keep_snapshot = [&] { keep(dem::scene::take_snapshot(sim)); };
  if (ck && ck->phase != "spin-up") {
    sampler.load(ck->sampler.at("state"));
    keep(ck->start_snapshot.value());
  } else {
    keep_snapshot();  // the film as sampling starts
  }
  while (sampled < static_cast<int>(std::floor(dc.sampling.turns + 1e-9))) {
    advance([&] { sampler.sample_turns(scene, 1.0); });
    ++sampled;
    sim.rebuild_lists();
    checkpoint("sampling", false);
  }
  if (sim.time() > snapshots.back().data.time) keep_snapshot();
  progress.update(sim.time(), sim.time() / period, particle_steps, true);
  progress.finish();
  checkpoint("done", dc.run.checkpoint_interval > 0.0);
  particle_steps += steps_before;
  const double wall = wall_before + progress.elapsed();

  DemRunResult r;
  r.engine = "centrec";
  r.engine_version = centrec::code_version();
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
  r.wall_time = wall;
  r.fields = sampler.fields();
  r.snapshots = std::move(snapshots);
  write_dem_run_report(out_dir, cf, dc, r);
}

}  // namespace centrec::cli
