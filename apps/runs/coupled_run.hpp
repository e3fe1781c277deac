#pragma once
// The coupled run behind `centrec run` (docs/architecture.md):
// DEM of the scaled-down drum -> its averaged film (coupling/dem_film_from_run, in memory;
// read back from dem.h5 when the DEM comes from the cache) ->
// the thermal film by the case's film mapping (coupling/film_mappings) -> its flux closure
// against the DEM's measured flow (coupling/film_mass_flow) -> scale-up to the receiver
// (coupling/film_scale_up) -> the case's mass flow imposed by one factor -> thermal steady
// state (and transient). A case that gives `film: {file: ...}` skips the DEM; so does a
// run given an earlier DEM-only run of the same DEM inputs (runs/earlier_dem_run.hpp).
// Refused unless allowed (then carried as warnings): a DEM drum below the scale-down
// validity threshold, a DEM not at steady flow, a flux closure off by more than 5 %.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "coupling/dem_film_averages.hpp"
#include "coupling/film_mappings.hpp"
#include "coupling/film_mass_flow.hpp"
#include "coupling/film_scale_up.hpp"
#include "runs/thermal_case_run.hpp"

namespace centrec::runs {

struct RunOptions {
  std::string cache_dir;          // DEM cache root (CACHE/<key>/)
  config::Overrides overrides;    // --threads, --speed-rpm, --mass-flow, --seed, --set
  bool allow_small_drum = false;  // run a DEM drum below coupling::kMinimumDrumDiameterOverD
  bool allow_unsteady = false;    // use a film that is not steady or fails the flux closure
  std::string dem_from;           // a finished `centrec dem` run of the same DEM inputs: its dem.h5, no DEM run
};

// A `centrec run` flag that sets a RunOptions member, declared once with its help (the
// case-value flags are config::Overrides', apps/cli/case_overrides.hpp): the command line
// adds every row, so a new option is its member here and its row in coupled_run.cpp.
struct RunOptionFlag {
  const char* name;
  const char* help;
  bool RunOptions::*on = nullptr;           // a switch, or
  std::string RunOptions::*text = nullptr;  // a value
  const char* value_name = "";              // the value's placeholder in the help ("DIR")
};
const std::vector<RunOptionFlag>& run_option_flags();

struct CoupledRun {
  config::DemCase dem;  // the DEM actually run (receiver derivation and overrides applied)
  bool has_receiver = false;
  config::ReceiverCase receiver;
  std::string dem_dir, cache_key;  // where dem.h5 came from
  bool dem_cached = false;
  bool dem_given = false;        // taken from RunOptions::dem_from
  std::string dem_resumed_from;  // the killed run's cache folder this run continued ("" = none)
  nlohmann::json dem_summary;
  coupling::DemFilmAverages averages;
  coupling::FilmMappingReport mapping;
  coupling::FlowClosure closure;
  coupling::ScaleUpRecord scale;
  coupling::ImposedFlow imposed;
  std::vector<std::string> warnings;  // what was allowed although not valid
  config::ThermalCase thermal;        // with the coupled film
  ThermalRun result;
  double dem_seconds = 0.0, mapping_seconds = 0.0, thermal_seconds = 0.0;

  // false: the case's analytic film or film file was used, no DEM.
  bool film_from_dem() const { return thermal.film_source.from_dem(); }
};

// Throws std::invalid_argument / std::runtime_error with a clear message on failure.
CoupledRun run_coupled_case(const config::CaseFile& cf, const RunOptions& o);
// What run_coupled_case refuses in its options before any work (the DEM's flags on a case
// without a DEM film, --dem-from with a changed operating point or seed): throws
// std::invalid_argument.
void check_run_options(const config::CaseFile& cf, const RunOptions& o);

}  // namespace centrec::runs
