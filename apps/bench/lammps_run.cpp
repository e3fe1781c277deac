#include "bench/lammps_run.hpp"

#include "bench/deck_run.hpp"
#include "liggghts/liggghts_launch.hpp"

namespace centrec::bench {

bool lammps_available(const LammpsRunSettings& r) { return liggghts::liggghts_available(r.mpirun, r.lammps); }

EngineResult run_lammps(const FilmCase& c, const FilmState& s, const LammpsRunSettings& r) {
  DeckRun d = deck_run_for("LAMMPS", "lammps_R", r.lammps, r, static_cast<long>(s.particles.size()));
  d.continued_runs = true;  // lammps_deck.cpp: timed runs without set-up
  write_lammps_deck(deck_path(d), c, s, r.deck);
  return run_deck(d);
}

}  // namespace centrec::bench
