#pragma once
// Runs LIGGGHTS 3.8 on the benchmark film with mpirun and collects its timings.
#include <string>

#include "bench/engine_result.hpp"
#include "bench/liggghts_deck.hpp"

namespace centrec::bench {

struct LiggghtsRunSettings {
  std::string liggghts = "liggghts";  // executable
  std::string mpirun = "mpirun";
  std::string work_dir;               // holds data file, STL, deck and log of this run
  LiggghtsDeckSettings deck;          // deck.ranks = MPI ranks
};

// Writes the deck into work_dir (the data and STL files named in `deck` must exist),
// runs it and parses the log. A failed run returns ok = false with a note; it does not throw.
EngineResult run_liggghts(const FilmCase& c, const FilmState& s, const LiggghtsRunSettings& r);

// True if `mpirun` and `liggghts` can be found on PATH.
bool liggghts_available(const LiggghtsRunSettings& r);

}  // namespace centrec::bench
