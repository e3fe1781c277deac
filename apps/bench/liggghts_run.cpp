#include "bench/liggghts_run.hpp"

#include "liggghts/liggghts_launch.hpp"
#include "bench/liggghts_log.hpp"

namespace centrec::bench {

bool liggghts_available(const LiggghtsRunSettings& r) { return liggghts::liggghts_available(r.mpirun, r.liggghts); }

EngineResult run_liggghts(const FilmCase& c, const FilmState& s, const LiggghtsRunSettings& r) {
  EngineResult res;
  res.engine = "LIGGGHTS";
  res.workers = r.deck.ranks;
  res.particles = static_cast<long>(s.particles.size());
  res.steps = r.deck.timed_steps;
  const std::string deck = r.work_dir + "/in.film_R" + std::to_string(r.deck.ranks);
  const std::string log = r.work_dir + "/log.film_R" + std::to_string(r.deck.ranks);
  write_liggghts_deck(deck, c, s, r.deck);
  liggghts::LiggghtsLaunch launch;
  launch.mpirun = r.mpirun;
  launch.liggghts = r.liggghts;
  launch.ranks = r.deck.ranks;
  launch.work_dir = r.work_dir;
  launch.deck = deck;
  launch.log = log;
  launch.screen = r.work_dir + "/screen.film_R" + std::to_string(r.deck.ranks);
  const std::string cmd = liggghts::liggghts_command(launch);
  const int rc = liggghts::run_shell(cmd);
  LiggghtsLog parsed;
  try {
    parsed = parse_liggghts_log(log);
  } catch (const std::exception& e) {
    res.note = e.what();
    return res;
  }
  res.seconds = parsed.timed_loop_seconds;
  res.settled = parsed.settled;
  res.list_pairs_per_particle = parsed.neighs_per_atom;
  if (!res.seconds.empty()) res.rebuilds_per_phase = static_cast<double>(parsed.timed_rebuilds) / res.seconds.size();
  res.final = parsed.final;
  res.bytes_per_particle = parsed.memory_mbytes_per_rank * 1024.0 * 1024.0 * r.deck.ranks / res.particles;
  res.ok = rc == 0 && parsed.error.empty() && parsed.have_final &&
           static_cast<int>(res.seconds.size()) == r.deck.repeats && parsed.final.atoms == res.particles;
  if (!res.ok)
    res.note = "LIGGGHTS failed (exit " + std::to_string(rc) + ")" +
               (parsed.error.empty() ? std::string() : ": " + parsed.error) + "; see " + log;
  return res;
}

}  // namespace centrec::bench
