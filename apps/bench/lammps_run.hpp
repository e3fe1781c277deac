#pragma once
// Runs LAMMPS (GRANULAR package) on the benchmark film with mpirun and collects its timings.
#include <string>

#include "bench/engine_result.hpp"
#include "bench/lammps_deck.hpp"

namespace centrec::bench {

struct LammpsRunSettings {
  std::string lammps = "lmp";  // executable
  std::string mpirun = "mpirun";
  std::string work_dir;        // holds the data file, deck and log of this run
  LammpsDeckSettings deck;     // deck.ranks = MPI ranks
};

// Writes the deck into work_dir (the data file named in `deck` must exist), runs it and
// parses the log. A failed run returns ok = false with a note; it does not throw.
EngineResult run_lammps(const FilmCase& c, const FilmState& s, const LammpsRunSettings& r);

// True if `mpirun` and the LAMMPS executable can be found on PATH.
bool lammps_available(const LammpsRunSettings& r);

}  // namespace centrec::bench
