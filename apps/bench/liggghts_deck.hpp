#pragma once
// The LIGGGHTS 3.8 input for the benchmark film: the data file (the initial state in
// LAMMPS data format) and the deck (settle, timed runs, final state report).
#include <string>

#include "bench/film_case.hpp"
#include "bench/film_initial_state.hpp"

namespace centrec::bench {

struct LiggghtsDeckSettings {
  std::string data_file;   // written by write_liggghts_data
  std::string stl_file;    // written by write_cylinder_stl
  double curvature_deg = 0.256235;  // fix mesh/surface curvature (cli::cylinder_curvature_deg)
  int ranks = 1;           // processor grid 1 x 1 x ranks (split along the drum axis)
  double skin = 0.48e-3;   // neighbour skin, m
  long settle_steps = 2000;
  long timed_steps = 1000;
  int repeats = 3;         // consecutive timed runs, each reported as its own "Loop time"
};

void write_liggghts_data(const std::string& path, const FilmCase& c, const FilmState& s);
void write_liggghts_deck(const std::string& path, const FilmCase& c, const FilmState& s,
                         const LiggghtsDeckSettings& k);

}  // namespace centrec::bench
