#pragma once
// Reads what the benchmark needs from a LIGGGHTS or LAMMPS log written by the decks of
// liggghts_deck.cpp and lammps_deck.cpp (LIGGGHTS keeps LAMMPS' log format): the "Loop
// time" of each timed run, the memory line, and the BENCH_STATE lines the decks print.
#include <string>

#include "bench/engine_result.hpp"

namespace centrec::bench {

struct LiggghtsLog {
  std::vector<double> timed_loop_seconds;  // one per timed run, in order
  std::vector<long> timed_loop_steps;
  long atoms_in_loop = 0;                  // atoms reported by the last timed "Loop time"
  double neighs_per_atom = 0.0;            // "Ave neighs/atom" of the last timed run
  long timed_rebuilds = 0;                 // "Neighbor list builds", summed over the timed runs
  long settle_rebuilds = 0;                // ... of the settle run
  long last_timed_rebuilds = 0;            // ... of the last timed run
  // LIGGGHTS: largest "Memory usage per processor" of the timed runs; LAMMPS: largest
  // average of "Per MPI rank memory allocation (min/avg/max)" (printed by initialised runs).
  double memory_mbytes_per_rank = 0.0;
  std::vector<double> timed_output_seconds;  // "Output" row (avg) of each timed run's timing breakdown
  bool have_settled = false, have_final = false;
  FilmSummary settled, final;
  std::string error;                       // first line containing "ERROR", if any
};

LiggghtsLog parse_liggghts_log(const std::string& path);

}  // namespace centrec::bench
