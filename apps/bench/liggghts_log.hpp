#pragma once
// Reads what the benchmark needs from a LIGGGHTS log written by the deck of
// liggghts_deck.cpp: the "Loop time" of each timed run, "Memory usage per processor"
// of the timed runs, and the BENCH_STATE lines the deck prints.
#include <string>

#include "bench/engine_result.hpp"

namespace centrec::bench {

struct LiggghtsLog {
  std::vector<double> timed_loop_seconds;  // one per timed run, in order
  std::vector<long> timed_loop_steps;
  long atoms_in_loop = 0;                  // atoms reported by the last timed "Loop time"
  double neighs_per_atom = 0.0;            // "Ave neighs/atom" of the last timed run
  long timed_rebuilds = 0;                 // "Neighbor list builds", summed over the timed runs
  double memory_mbytes_per_rank = 0.0;     // largest "Memory usage per processor" of the timed runs
  bool have_settled = false, have_final = false;
  FilmSummary settled, final;
  std::string error;                       // first line containing "ERROR", if any
};

LiggghtsLog parse_liggghts_log(const std::string& path);

}  // namespace centrec::bench
