#include "bench/liggghts_run.hpp"

#include "bench/deck_run.hpp"
#include "liggghts/liggghts_launch.hpp"

namespace centrec::bench {

bool liggghts_available(const LiggghtsRunSettings& r) { return liggghts::liggghts_available(r.mpirun, r.liggghts); }

EngineResult run_liggghts(const FilmCase& c, const FilmState& s, const LiggghtsRunSettings& r) {
  const DeckRun d = deck_run_for("LIGGGHTS", "film_R", r.liggghts, r, static_cast<long>(s.particles.size()));
  write_liggghts_deck(deck_path(d), c, s, r.deck);
  return run_deck(d);
}

}  // namespace centrec::bench
