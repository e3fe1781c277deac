#pragma once
// The benchmark's results table: printed, and written as CSV and markdown.
#include <string>
#include <vector>

#include "bench/engine_result.hpp"
#include "bench/film_case.hpp"

namespace centrec::bench {

// One (N, workers) point; any engine may be missing (ok = false, e.g. --no-liggghts).
struct BenchRow {
  long particles = 0;
  int workers = 1;
  EngineResult centrec, liggghts, lammps;
};

// Markdown: the speed table, then the film state each engine reached (to show all
// advanced the same system). Cost per particle is relative to the smallest N at the same
// worker count.
std::string format_markdown(const FilmCase& fc, const std::vector<BenchRow>& rows, const std::string& preamble);
void write_csv(const std::string& path, const std::vector<BenchRow>& rows);
void write_text(const std::string& path, const std::string& text);

}  // namespace centrec::bench
