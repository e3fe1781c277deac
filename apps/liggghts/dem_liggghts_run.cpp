#include "liggghts/dem_liggghts_run.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "liggghts/liggghts_dump.hpp"
#include "liggghts/liggghts_export.hpp"
#include "liggghts/liggghts_log_reader.hpp"
#include "runs/progress_meter.hpp"

namespace centrec::liggghts {

std::vector<dem::scene::MassFlowSample> read_liggghts_mass_flow(const std::string& path, double initial_holdup,
                                                                 const std::string& prefix) {
  std::vector<dem::scene::MassFlowSample> log;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind(prefix, 0) != 0) continue;
    std::istringstream l(line.substr(prefix.size()));
    dem::scene::MassFlowSample s;
    double n = 0.0;
    if (!(l >> s.time >> s.fed >> s.out >> s.holdup >> n)) break;  // a line being written
    s.particles = static_cast<std::int64_t>(std::llround(n));
    double axial = 0.0;
    if (l >> axial) s.axial_flow = axial;  // a slice's sum(m v_z) / L (decks before it have 5 columns)
    // Mass balance: whatever is neither held up nor out left through the box (lost).
    s.lost = std::max(0.0, initial_holdup + s.fed - s.out - s.holdup);
    if (s.lost < 1e-9 * (initial_holdup + s.fed)) s.lost = 0.0;  // round-off of the sums
    log.push_back(s);
  }
  return log;
}

namespace {

std::string failure_report(const std::string& what, const LiggghtsLogSummary& log, const std::string& log_path,
                           const std::string& screen_path) {
  std::string msg = what;
  for (const auto& e : log.errors) msg += "\n" + e;
  if (log.errors.empty()) {
    // Nothing in the log (e.g. the launcher failed): show the end of the screen output.
    std::ifstream in(screen_path);
    std::vector<std::string> tail;
    std::string line;
    while (std::getline(in, line)) {
      tail.push_back(line);
      if (tail.size() > 8) tail.erase(tail.begin());
    }
    for (const auto& t : tail) msg += "\n  | " + t;
  }
  return msg + "\n(see " + log_path + " and " + screen_path + ")";
}

}  // namespace

io::DemRunResult run_dem_on_liggghts(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                                 LiggghtsLaunch launch) {
  if (!liggghts_available(launch.mpirun, launch.liggghts))
    throw std::runtime_error("LIGGGHTS not found: need `" + launch.mpirun + "` and `" + launch.liggghts +
                             "` on PATH: install them with `./setup.sh --with-liggghts` (Debian packages liggghts and "
                             "openmpi-bin), or give --mpirun / --liggghts");
  const std::string dir = out_dir + "/liggghts";
  const LiggghtsDeckPlan plan = export_liggghts(cf, dc, dir);
  launch.work_dir = dir;
  launch.deck = plan.deck;
  launch.log = plan.log;
  launch.screen = plan.screen;
  std::remove((dir + "/" + plan.flow_file).c_str());
  for (const auto& f : list_dump_files(dir + "/" + plan.dump_dir, "film_", ".dump")) std::remove(f.c_str());

  const double period = dem::scene::turn_period(dc.scene);
  const double total = (plan.spinup_steps + plan.sampling_steps) * plan.dt;
  const std::int64_t sampling_start = plan.spinup_steps;
  std::fprintf(stderr, "centrec dem (LIGGGHTS, %d rank(s)): %s\n  dt = %.3g s, %lld glued + %lld free particles\n",
               launch.ranks, cf.path.c_str(), plan.dt, static_cast<long long>(plan.glued),
               static_cast<long long>(plan.initial_free));
  for (const std::string& d : plan.differences)
    std::fprintf(stderr, "centrec dem: warning: the LIGGGHTS run differs from the native engine: %s\n", d.c_str());

  dem::scene::SceneSampler sampler(dc.scene, dc.sampling.sampler);
  io::DemRunResult r;
  r.snapshot_stride = io::snapshot_stride(static_cast<double>(plan.sampled_turns) * plan.snapshots_per_turn,
                                          static_cast<double>(plan.initial_free + plan.glued));
  std::size_t fed_dumps = 0;  // dumps taken into the sampler (the first, at sampling start, is kept only)
  auto take_dumps = [&](bool finished) {
    const auto files = list_dump_files(dir + "/" + plan.dump_dir, "film_", ".dump");
    // A dump is complete once a later one exists or LIGGGHTS has ended.
    const std::size_t ready = finished ? files.size() : (files.empty() ? 0 : files.size() - 1);
    for (std::size_t k = fed_dumps; k < ready; ++k) {
      const std::int64_t step = dump_file_step(files[k]);
      dem::scene::SnapshotArrays s = read_liggghts_dump(files[k], plan.dt);
      const std::int64_t index = (step - sampling_start) / plan.dump_every;  // 0 = sampling start
      char name[32];
      std::snprintf(name, sizeof name, "t%.6f", s.time);
      // Every stride-th dump from the sampling start, and the last (free particles only).
      if (index >= 0 && (index % r.snapshot_stride == 0 || step == sampling_start + plan.sampling_steps))
        r.snapshots.push_back({name, s, {}});
      if (index > 0) {
        sampler.add_snapshot(std::move(s));
        if (index % plan.snapshots_per_turn == 0) sampler.end_turn();
      }
    }
    fed_dumps = std::max(fed_dumps, ready);
  };

  runs::ProgressMeter progress(total, dc.run.progress_interval);
  char what[128];
  std::snprintf(what, sizeof what, "spin-up to t = %.4g s, then %d sampled turn(s), in LIGGGHTS",
                static_cast<double>(plan.spinup_steps) * plan.dt, plan.sampled_turns);
  progress.phase("liggghts", what);
  double particle_steps = 0.0;
  auto poll = [&] {
    const auto log = read_liggghts_mass_flow(dir + "/" + plan.flow_file, plan.initial_holdup);
    if (!log.empty()) {
      // Particle-steps: free particles (trapezoid over records) plus the glued ones.
      particle_steps = 0.0;
      double t0 = 0.0, n0 = static_cast<double>(plan.initial_free);
      for (const auto& s : log) {
        const double n1 = static_cast<double>(s.particles);
        particle_steps += (0.5 * (n0 + n1) + static_cast<double>(plan.glued)) * (s.time - t0) / plan.dt;
        t0 = s.time;
        n0 = n1;
      }
      progress.update(log.back().time, log.back().time / period, particle_steps);
    }
    take_dumps(false);
  };
  const int rc = run_shell_polling(liggghts_command(launch), poll, 0.5);
  const std::string log_path = dir + "/" + plan.log, screen_path = dir + "/" + plan.screen;
  LiggghtsLogSummary log = read_liggghts_log(log_path);
  // Some errors ("ERROR on proc N") reach only the screen output.
  if (log.errors.empty()) log.errors = read_liggghts_log(screen_path).errors;
  if (rc != 0 || !log.errors.empty() || log.loops.size() < 2)
    throw std::runtime_error(failure_report("LIGGGHTS failed (exit status " + std::to_string(rc) + ", " +
                                                std::to_string(log.loops.size()) + " of 2 runs completed)",
                                            log, log_path, screen_path));
  take_dumps(true);
  progress.update(total, total / period, particle_steps, true);
  progress.finish();

  r.engine = "liggghts";
  r.engine_version = log.version.empty() ? "unknown" : log.version;
  r.threads = 1;
  r.ranks = launch.ranks;
  r.dt = plan.dt;
  r.steps = plan.spinup_steps + plan.sampling_steps;
  r.simulated_time = static_cast<double>(r.steps) * plan.dt;
  r.glued_particles = plan.glued;
  r.mass_flow = read_liggghts_mass_flow(dir + "/" + plan.flow_file, plan.initial_holdup);
  const auto final_state = read_liggghts_mass_flow(log_path, plan.initial_holdup, "CENTREC_FINAL ");
  if (final_state.empty()) throw std::runtime_error("no CENTREC_FINAL line in " + log_path);
  if (r.mass_flow.empty() || final_state.back().time > r.mass_flow.back().time + 0.5 * plan.dt)
    r.mass_flow.push_back(final_state.back());
  dem::scene::MassFlowSample start;
  start.holdup = plan.initial_holdup;
  start.particles = plan.initial_free;
  r.mass_flow.insert(r.mass_flow.begin(), start);  // the native log also starts at t = 0
  r.free_particles = r.mass_flow.back().particles;
  r.holdup_kg = r.mass_flow.back().holdup;
  r.feeder_deferred = -1;          // LIGGGHTS reports failed insertions only as warnings
  r.contacts_per_particle = -1.0;  // not reported by the deck
  r.particle_steps = particle_steps;
  r.wall_time = progress.elapsed();
  r.fields = sampler.fields();
  if (r.mass_flow.back().lost > 0.0) {
    std::fprintf(stderr, "centrec dem: LIGGGHTS lost %.3g kg of particles (mass balance); its warnings:\n",
                 r.mass_flow.back().lost);
    for (const auto& w : log.warnings) std::fprintf(stderr, "  %s\n", w.c_str());
  }
  return r;
}

runs::DemEngine liggghts_engine(const LiggghtsLaunch& launch) {
  return [launch](const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir) {
    return run_dem_on_liggghts(cf, dc, out_dir, launch);
  };
}

}  // namespace centrec::liggghts
