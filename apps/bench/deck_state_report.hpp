#pragma once
// The film-state report of the LAMMPS-family decks (LIGGGHTS 3.8 and LAMMPS share the
// input language): the per-atom variables, computes and equal-style variables behind a
// "BENCH_STATE" line, computed as film_summary.cpp computes it for centrec, so the results
// table shows every engine advancing the same film.
#include <string>

namespace centrec::bench {

// Variable and compute definitions. Wall contacts are counted geometrically (centre
// within wall_r of the axis: R - d/2) because neither engine keeps a per-atom wall contact
// count the same way; pair contacts come from `compute contact/atom` (2 x pairs).
std::string state_report_definitions(double wall_r);

// The thermo columns that make the report's computes current at a run's end.
const char* state_thermo_columns();

// `print "BENCH_STATE <tag> atoms ... wall_contacts ..."` (read by parse_liggghts_log).
std::string state_print_command(const char* tag);

}  // namespace centrec::bench
