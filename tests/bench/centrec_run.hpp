#pragma once
// Runs the centrec DEM engine on the benchmark film: the same initial state, settle and
// timed phases as the LIGGGHTS deck.
#include "tests/bench/engine_result.hpp"
#include "tests/bench/film_case.hpp"
#include "tests/bench/film_initial_state.hpp"

namespace centrec::bench {

struct CentrecRunSettings {
  int threads = 1;
  double skin_fraction = 0.4;  // Verlet skin / d
  long settle_steps = 2000;
  long timed_steps = 1000;
  int repeats = 3;             // consecutive timed phases
};

EngineResult run_centrec(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r);

}  // namespace centrec::bench
