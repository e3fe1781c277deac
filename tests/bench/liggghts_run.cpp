#include "tests/bench/liggghts_run.hpp"

#include <unistd.h>

#include <cstdlib>
#include <sys/wait.h>

#include "tests/bench/liggghts_log.hpp"

namespace centrec::bench {
namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

int run_shell(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  if (status == -1) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

bool liggghts_available(const LiggghtsRunSettings& r) {
  return run_shell("command -v " + quoted(r.mpirun) + " >/dev/null 2>&1 && command -v " + quoted(r.liggghts) +
                   " >/dev/null 2>&1") == 0;
}

EngineResult run_liggghts(const FilmCase& c, const FilmState& s, const LiggghtsRunSettings& r) {
  EngineResult res;
  res.engine = "LIGGGHTS";
  res.workers = r.deck.ranks;
  res.particles = static_cast<long>(s.particles.size());
  res.steps = r.deck.timed_steps;
  const std::string deck = r.work_dir + "/in.film_R" + std::to_string(r.deck.ranks);
  const std::string log = r.work_dir + "/log.film_R" + std::to_string(r.deck.ranks);
  write_liggghts_deck(deck, c, s, r.deck);
  // Screen output goes to a file: "-screen none" crashes the Debian LIGGGHTS 3.8 build
  // (segfault before the first line). --bind-to none: OpenMPI would otherwise pin ranks to cores that other processes of
  // this (shared) machine also use; --oversubscribe: never refuse 2 ranks on 2 cores.
  std::string cmd = "cd " + quoted(r.work_dir) + " && " + quoted(r.mpirun);
  if (geteuid() == 0) cmd += " --allow-run-as-root";
  cmd += " --oversubscribe --bind-to none -np " + std::to_string(r.deck.ranks) + " " + quoted(r.liggghts) +
         " -in " + quoted(deck) + " -log " + quoted(log) + " > " +
         quoted(r.work_dir + "/screen.film_R" + std::to_string(r.deck.ranks)) + " 2>&1";
  const int rc = run_shell(cmd);
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
