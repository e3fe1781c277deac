#pragma once
// Runs a LAMMPS-family deck (LIGGGHTS 3.8 or LAMMPS) under MPI and reads its log into the
// benchmark's EngineResult: the launch and log handling both peer engines share.
#include <string>

#include "bench/engine_result.hpp"

namespace centrec::bench {

struct DeckRun {
  std::string engine;    // "LIGGGHTS", "LAMMPS": the table's name
  std::string mpirun = "mpirun";
  std::string exe;       // the engine's executable
  std::string work_dir;  // holds the deck (in.<tag>); log.<tag> and screen.<tag> go there
  std::string tag;
  int ranks = 1;
  long particles = 0;
  long timed_steps = 0;
  int repeats = 0;
  // The timed runs continue without set-up (`run N pre no`, the LAMMPS deck): their
  // "Output" time is the state report riding in every run's thermo and is taken out of
  // the loop time, and their neighbour-build counters run on from the settle's.
  bool continued_runs = false;
};

// A run of `engine` from its run settings (mpirun, work_dir, deck.ranks / timed_steps /
// repeats); tag = tag_stem + ranks.
template <class RunSettings>
DeckRun deck_run_for(const char* engine, const char* tag_stem, const std::string& exe, const RunSettings& r,
                     long particles) {
  DeckRun d;
  d.engine = engine;
  d.mpirun = r.mpirun;
  d.exe = exe;
  d.work_dir = r.work_dir;
  d.tag = tag_stem + std::to_string(r.deck.ranks);
  d.ranks = r.deck.ranks;
  d.particles = particles;
  d.timed_steps = r.deck.timed_steps;
  d.repeats = r.deck.repeats;
  return d;
}

std::string deck_path(const DeckRun& r);  // work_dir/in.<tag>

// Runs the deck written at deck_path(r) and parses its log. A failed run returns ok =
// false with a note; it does not throw.
EngineResult run_deck(const DeckRun& r);

}  // namespace centrec::bench
