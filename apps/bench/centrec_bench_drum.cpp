// centrec_bench_drum: the fed drum's speed (apps/bench/README.md "centrec_bench_drum").
// Starts from the checkpoint of a `centrec dem` run of a fed drum (its steady state) and
// times centrec on 1 and 2 threads, then LIGGGHTS 3.8 on the identical drum (the deck of
// `centrec export-liggghts`, written from the same state) on 1 and 2 MPI ranks, in one run.
// centrec: `--settle` untimed steps, then `--repeats` timed phases of `--steps` steps each
// (CentrecScene::advance: feeder, outlet and bookkeeping included), the median phase; the
// time per phase from the engine's and the scene's own timers. LIGGGHTS: one timed run of
// about repeats x steps steps (its "Loop time"). Figures: particle-steps/s counting every
// particle and counting the free (moving) ones only, per core, and the ratio to LIGGGHTS.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "io/atomic_write.hpp"
#include "io/checkpoint_h5.hpp"
#include "liggghts/liggghts_export.hpp"
#include "liggghts/liggghts_launch.hpp"
#include "liggghts/liggghts_log_reader.hpp"
#include "runs/settled_start.hpp"

namespace {

using namespace centrec;

struct Row {
  std::string engine;
  int threads = 0;        // threads (centrec) or MPI ranks (LIGGGHTS)
  double all = 0.0;       // particle-steps/s, every particle
  double moving = 0.0;    // particle-steps/s, free particles only
  std::vector<double> phase_seconds;  // centrec: median-phase shares (names below)
  double seconds = 0.0;   // median timed phase (centrec) or the timed run (LIGGGHTS)
  long steps = 0;
  double particles = 0.0, free_particles = 0.0;
  long rebuilds = 0, edits = 0;
  std::string note;
};

const char* kPhaseNames[] = {"force pass", "of which waiting (pair / parked pass)", "first half", "neighbour build",
                             "list edits", "insertion", "outlet", "bookkeeping"};

std::vector<double> phase_times(const dem::scene::CentrecScene& scene) {
  const dem::EngineTimes& e = scene.simulation().times();
  const dem::scene::SceneTimes& t = scene.times();
  return {e.force_pass, e.pair_pass_idle, e.parked_pass_idle, e.first_half, e.neighbour_build, e.list_edit,
          t.insertion, t.outlet, t.bookkeeping};
}

Row time_centrec(const config::DemCase& dc, const io::RunCheckpoint& ck, int threads, long settle, long steps,
                 int repeats) {
  config::DemCase d = dc;
  d.scene.threads = threads;
  dem::scene::CentrecScene scene(d.scene, ck.scene);
  const double dt = scene.simulation().dt();
  if (settle > 0) scene.advance(static_cast<double>(settle) * dt);
  struct Phase {
    double seconds, particle_steps, moving_steps;
    std::vector<double> shares;
    long rebuilds, edits;
  };
  std::vector<Phase> phases;
  for (int r = 0; r < repeats; ++r) {
    const auto& sim = scene.simulation();
    const double n0 = static_cast<double>(sim.size()), f0 = static_cast<double>(scene.free_particles());
    const std::vector<double> p0 = phase_times(scene);
    const auto ns0 = sim.neighbour_stats();
    const auto t0 = std::chrono::steady_clock::now();
    scene.advance(static_cast<double>(steps) * dt);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::vector<double> p1 = phase_times(scene);
    std::vector<double> share(p0.size());
    for (std::size_t k = 0; k < p0.size(); ++k) share[k] = p1[k] - p0[k];
    const auto ns1 = sim.neighbour_stats();
    phases.push_back({s, 0.5 * (n0 + static_cast<double>(sim.size())) * steps,
                      0.5 * (f0 + static_cast<double>(scene.free_particles())) * steps, share,
                      static_cast<long>(ns1.rebuilds - ns0.rebuilds), static_cast<long>(ns1.list_edits - ns0.list_edits)});
  }
  std::vector<std::size_t> order(phases.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return phases[a].seconds < phases[b].seconds; });
  const Phase& m = phases[order[order.size() / 2]];
  Row row;
  row.engine = "centrec";
  row.threads = threads;
  row.seconds = m.seconds;
  row.steps = steps;
  row.all = m.particle_steps / m.seconds;
  row.moving = m.moving_steps / m.seconds;
  row.phase_seconds = m.shares;
  row.particles = m.particle_steps / steps;
  row.free_particles = m.moving_steps / steps;
  row.rebuilds = m.rebuilds;
  row.edits = m.edits;
  char b[128];
  std::snprintf(b, sizeof b, "phases %.3g-%.3g s (median %.3g)", phases[order.front()].seconds,
                phases[order.back()].seconds, m.seconds);
  row.note = b;
  return row;
}

Row time_liggghts(const config::CaseFile& cf, const config::DemCase& dc, const io::RunCheckpoint& ck, int ranks,
                  long steps, const std::string& dir) {
  Row row;
  row.engine = "LIGGGHTS 3.8";
  row.threads = ranks;
  config::DemCase d = dc;
  d.run.duration = static_cast<double>(steps) * d.scene.dt;  // one timed run (rounded up to dump intervals)
  d.sampling.turns = 0;
  d.initial_film_from_run.clear();  // the checkpoint's state is the starting film
  const liggghts::LiggghtsDeckPlan plan = liggghts::export_liggghts(cf, d, dir, &ck.scene);
  liggghts::LiggghtsLaunch l;
  l.ranks = ranks;
  l.work_dir = dir;
  l.deck = plan.deck;
  l.log = plan.log;
  l.screen = plan.screen;
  const int status = liggghts::run_shell(liggghts::liggghts_command(l));
  const liggghts::LiggghtsLogSummary log = liggghts::read_liggghts_log(dir + "/" + plan.log);
  if (status != 0 || log.loops.empty()) {
    row.note = "failed (exit " + std::to_string(status) + (log.errors.empty() ? "" : "): " + log.errors.front());
    return row;
  }
  const liggghts::LiggghtsLoopTime& loop = log.loops.front();  // the spin-up run: the timed one
  row.seconds = loop.seconds;
  row.steps = loop.steps;
  row.particles = static_cast<double>(loop.atoms);
  row.free_particles = static_cast<double>(loop.atoms - plan.glued);
  row.all = row.particles * static_cast<double>(loop.steps) / loop.seconds;
  row.moving = row.free_particles * static_cast<double>(loop.steps) / loop.seconds;
  row.note = "one run of " + std::to_string(loop.steps) + " steps; atoms at its end";
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "centrec_bench_drum: the fed drum's DEM speed, centrec against LIGGGHTS 3.8 on the identical drum, from the\n"
      "steady checkpoint of a `centrec dem` run (DIR/checkpoint.h5)"};
  std::string from, out = "bench-drum";
  std::vector<int> threads{1, 2};
  long steps = 500, settle = 500;
  int repeats = 3;
  bool no_liggghts = false;
  double skin_d = 0.0;
  app.add_option("--from", from, "a `centrec dem` run folder of a fed drum with its checkpoint.h5")->required();
  app.add_option("--threads", threads, "centrec threads and LIGGGHTS ranks to time (default 1 2)");
  app.add_option("--steps", steps, "steps per timed phase (default 500)");
  app.add_option("--repeats", repeats, "timed phases per row; the median is reported (default 3)");
  app.add_option("--settle", settle, "untimed steps before the timed phases (default 500)");
  app.add_flag("--no-liggghts", no_liggghts, "time centrec only");
  app.add_option("--skin-d", skin_d, "centrec's Verlet skin in particle diameters (default: the run's run.skin_d)");
  app.add_option("--out", out, "folder for the LIGGGHTS decks and results.md (default bench-drum)");
  CLI11_PARSE(app, argc, argv);
  try {
    const io::RunCheckpoint ck = io::read_checkpoint(from);
    // Both engines run the wall rolling LIGGGHTS' mesh walls can express (docs/dem_physics.md).
    const bool peers = !no_liggghts && liggghts::liggghts_available("mpirun", "liggghts");
    config::Overrides o;
    if (peers) o.keys["dem.contacts.wall_rolling_model"] = "liggghts";
    const config::CaseFile cf = config::with_overrides(runs::drum_case_of(ck), o);
    const config::DemCase dc = config::effective_dem(*cf.dem, cf.receiver ? &*cf.receiver : nullptr, {});
    if (dc.scene.slice.enabled || !dc.scene.feeder.enabled)
      throw std::invalid_argument(from + ": not a fed drum (this benchmark times the feeder and the outlet too)");
    config::DemCase centrec_dc = dc;
    if (skin_d > 0.0) centrec_dc.scene.skin = skin_d * dc.scene.particle.diameter;
    io::ensure_directory(out);
    std::vector<Row> rows;
    for (int t : threads) {
      std::fprintf(stderr, "centrec, %d thread(s)...\n", t);
      rows.push_back(time_centrec(centrec_dc, ck, t, settle, steps, repeats));
    }
    if (peers)
      for (int t : threads) {
        std::fprintf(stderr, "LIGGGHTS, %d rank(s)...\n", t);
        rows.push_back(time_liggghts(cf, dc, ck, t, steps * repeats, out + "/liggghts_np" + std::to_string(t)));
      }
    else if (!no_liggghts)
      std::fprintf(stderr, "centrec_bench_drum: mpirun or liggghts not on PATH: centrec only\n");

    std::string md;
    char b[512];
    std::snprintf(b, sizeof b,
                  "# centrec_bench_drum\n\nFrom %s (t = %.4g s), wall rolling model %s, dt %.3g s, %ld settle steps, "
                  "%d x %ld timed steps.\n\n"
                  "| engine | threads/ranks | particles (free) | particle-steps/s | per core | free particle-steps/s | "
                  "per core | ratio to LIGGGHTS (same count) | rebuilds / list edits per phase | note |\n"
                  "|---|---|---|---|---|---|---|---|---|---|\n",
                  from.c_str(), ck.scene.engine.time,
                  dc.scene.wall_rolling == dem::WallRolling::liggghts ? "liggghts" : "relative", dc.scene.dt, settle,
                  repeats, steps);
    md += b;
    for (const Row& r : rows) {
      const Row* peer = nullptr;
      for (const Row& p : rows)
        if (p.engine != "centrec" && p.threads == r.threads && p.all > 0.0) peer = &p;
      std::string ratio = "-";
      if (r.engine == "centrec" && peer) {
        std::snprintf(b, sizeof b, "%.2f", r.all / peer->all);
        ratio = b;
      }
      std::snprintf(b, sizeof b, "| %s | %d | %.0f (%.0f) | %.3g | %.3g | %.3g | %.3g | %s | %s | %s |\n",
                    r.engine.c_str(), r.threads, r.particles, r.free_particles, r.all, r.all / r.threads, r.moving,
                    r.moving / r.threads, ratio.c_str(),
                    r.engine == "centrec" ? (std::to_string(r.rebuilds) + " / " + std::to_string(r.edits)).c_str() : "-",
                    r.note.c_str());
      md += b;
    }
    md += "\ncentrec's median phase by part (s, share of the phase):\n\n| threads |";
    for (const char* name : kPhaseNames) md += std::string(" ") + name + " |";
    md += " rest |\n|---|";
    for (std::size_t k = 0; k <= std::size(kPhaseNames); ++k) md += "---|";
    md += "\n";
    for (const Row& r : rows) {
      if (r.engine != "centrec") continue;
      md += "| " + std::to_string(r.threads) + " |";
      double timed = 0.0;
      for (std::size_t k = 0; k < r.phase_seconds.size(); ++k) {
        const double s = r.phase_seconds[k];
        if (k == 1) {  // the waits are part of the force pass: one cell, not counted twice
          std::snprintf(b, sizeof b, " %.3g / %.3g (%.0f %%) |", s, r.phase_seconds[2],
                        100.0 * (s + r.phase_seconds[2]) / r.seconds);
          md += b;
          ++k;
          continue;
        }
        timed += s;
        std::snprintf(b, sizeof b, " %.3g (%.0f %%) |", s, 100.0 * s / r.seconds);
        md += b;
      }
      std::snprintf(b, sizeof b, " %.3g (%.0f %%) |\n", r.seconds - timed, 100.0 * (r.seconds - timed) / r.seconds);
      md += b;
    }
    io::write_text_atomically(out + "/results.md", md);
    std::fputs(md.c_str(), stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "centrec_bench_drum: %s\n", e.what());
    return 1;
  }
  return 0;
}
