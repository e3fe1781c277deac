#include "bench/deck_run.hpp"

#include "bench/liggghts_log.hpp"
#include "liggghts/liggghts_launch.hpp"

namespace centrec::bench {

std::string deck_path(const DeckRun& r) { return r.work_dir + "/in." + r.tag; }

EngineResult run_deck(const DeckRun& r) {
  EngineResult res;
  res.engine = r.engine;
  res.workers = r.ranks;
  res.particles = r.particles;
  res.steps = r.timed_steps;
  const std::string log = r.work_dir + "/log." + r.tag;
  // LIGGGHTS' launcher takes any executable with LAMMPS' command line (-in, -log).
  liggghts::LiggghtsLaunch launch;
  launch.mpirun = r.mpirun;
  launch.liggghts = r.exe;
  launch.ranks = r.ranks;
  launch.work_dir = r.work_dir;
  launch.deck = deck_path(r);
  launch.log = log;
  launch.screen = r.work_dir + "/screen." + r.tag;
  const int rc = liggghts::run_shell(liggghts::liggghts_command(launch));
  LiggghtsLog parsed;
  try {
    parsed = parse_liggghts_log(log);
  } catch (const std::exception& e) {
    res.note = e.what();
    return res;
  }
  res.seconds = parsed.timed_loop_seconds;
  if (r.continued_runs && parsed.timed_output_seconds.size() == res.seconds.size())
    for (std::size_t i = 0; i < res.seconds.size(); ++i) res.seconds[i] -= parsed.timed_output_seconds[i];
  const long timed_builds =
      r.continued_runs ? parsed.last_timed_rebuilds - parsed.settle_rebuilds : parsed.timed_rebuilds;
  res.settled = parsed.settled;
  res.list_pairs_per_particle = parsed.neighs_per_atom;
  if (!res.seconds.empty()) res.rebuilds_per_phase = static_cast<double>(timed_builds) / res.seconds.size();
  res.final = parsed.final;
  res.bytes_per_particle = parsed.memory_mbytes_per_rank * 1024.0 * 1024.0 * r.ranks / res.particles;
  res.ok = rc == 0 && parsed.error.empty() && parsed.have_final && static_cast<int>(res.seconds.size()) == r.repeats &&
           parsed.final.atoms == res.particles;
  if (!res.ok)
    res.note = r.engine + " failed (exit " + std::to_string(rc) + ")" +
               (parsed.error.empty() ? std::string() : ": " + parsed.error) + "; see " + log;
  return res;
}

}  // namespace centrec::bench
