#pragma once
// Runs the centrec DEM engine on the benchmark film: the same initial state, settle and
// timed phases as the LIGGGHTS deck.
#include <memory>

#include "bench/engine_result.hpp"
#include "bench/film_case.hpp"
#include "bench/film_initial_state.hpp"

namespace centrec::bench {

struct CentrecRunSettings {
  int threads = 1;
  double skin_fraction = 0.4;  // Verlet skin / d
  long settle_steps = 2000;
  long timed_steps = 1000;
  int repeats = 3;             // consecutive timed phases: one window
  int replays = 1;             // windows, each from the post-settle state (bit for bit the same run)
};

// One centrec film: built and settled on construction, then timed one phase at a time, so
// that the phases of several films can be interleaved (a slow spell of a shared machine
// then hits every size, not one).
class CentrecFilmRun {
 public:
  CentrecFilmRun(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r);
  ~CentrecFilmRun();
  CentrecFilmRun(const CentrecFilmRun&) = delete;
  CentrecFilmRun& operator=(const CentrecFilmRun&) = delete;
  // One timed phase of r.timed_steps (no-op after a failure). After the window's last
  // phase, the next call first rewinds (untimed) to the post-settle state.
  void time_phase();
  EngineResult finish();  // final state and statistics

 private:
  struct State;
  std::unique_ptr<State> st_;
};

// Settle and r.replays windows of r.repeats consecutive timed phases.
EngineResult run_centrec(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r);

}  // namespace centrec::bench
