#include "runs/coupled_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "coupling/dem_film_from_run.hpp"
#include "dem/scene/scene_config.hpp"
#include "io/code_version.hpp"
#include "io/dem_film_h5.hpp"
#include "io/summary_json.hpp"
#include "runs/dem_cache.hpp"
#include "runs/dem_case_run.hpp"
#include "runs/earlier_dem_run.hpp"
#include "runs/interrupt.hpp"

namespace centrec::runs {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The DEM inputs as they will run: receiver derivation, then the command-line overrides
// (config::effective_dem, the same as `centrec dem` and the case checks).
void effective_dem(const config::CaseFile& cf, const RunOptions& o, CoupledRun& r) {
  const config::Overrides& ov = o.overrides;
  r.has_receiver = cf.receiver.has_value();
  if (cf.receiver) r.receiver = config::effective_receiver(*cf.receiver, ov);
  r.dem = config::effective_dem(*cf.dem, cf.receiver ? &*cf.receiver : nullptr, ov);
}

// A condition the coupled run refuses unless its flag allows it; allowed, it becomes a
// warning on stderr and in the outputs. `problem` "" = nothing to refuse.
void allow_or_refuse(CoupledRun& r, const std::string& problem, bool allowed, const char* flag,
                     const std::string& where) {
  if (problem.empty()) return;
  if (!allowed) throw std::invalid_argument(where + ": " + problem + "; " + flag + " runs it anyway (with a warning)");
  std::fprintf(stderr, "centrec run: WARNING: %s (allowed by %s)\n", problem.c_str(), flag);
  r.warnings.push_back(problem);
}

}  // namespace

const std::vector<RunOptionFlag>& run_option_flags() {
  static const std::vector<RunOptionFlag> flags = {
      {"--cache", "the DEM cache (default: the parent of DIR + /dem-cache)", nullptr, &RunOptions::cache_dir, "DIR"},
      {"--dem-from", "take the film of a finished `centrec dem` run of the same DEM inputs", nullptr,
       &RunOptions::dem_from, "DEM_DIR"},
      {"--allow-small-drum", "run a DEM drum below the scale-down validity threshold (the outputs carry a warning)",
       &RunOptions::allow_small_drum},
      {"--allow-unsteady", "use a DEM film that is not at steady flow or misses the flux closure (with a warning)",
       &RunOptions::allow_unsteady},
  };
  return flags;
}

void check_run_options(const config::CaseFile& cf, const RunOptions& o) {
  if (!cf.thermal) throw std::invalid_argument(cf.path + ": a coupled run needs a `thermal:` section");
  const bool from_dem = cf.thermal->film_source.from_dem();
  if (!o.dem_from.empty() && (!from_dem || o.overrides.any_operating_point() || o.overrides.sets("dem.seed")))
    throw std::invalid_argument(cf.path +
                                ": --dem-from takes the film of an earlier DEM run as it ran; it goes with "
                                "neither a case without a DEM film nor --speed-rpm, --mass-flow or --seed");
  if (!from_dem && o.overrides.any_dem())
    throw std::invalid_argument(cf.path +
                                ": the DEM's flags (--speed-rpm, --mass-flow, --seed, --threads, --set dem.*) "
                                "change or run the DEM, but this case takes its film from " +
                                cf.thermal->film_source.text() + " (no DEM runs)");
}

CoupledRun run_coupled_case(const config::CaseFile& given, const RunOptions& o) {
  check_run_options(given, o);
  // The command line's case keys written into the case (the same case again when they are
  // there already).
  const config::CaseFile cf = config::with_overrides(given, o.overrides);
  CoupledRun r;
  r.thermal = *cf.thermal;
  if (r.film_from_dem()) {
    if (!cf.dem) throw std::invalid_argument(cf.path + ": give a `dem:` section or `film: {file: ...}`");
    effective_dem(cf, o, r);
    // The case reader's checks, on the DEM and receiver as they will run.
    if (const auto p = config::coupled_run_problem(r.dem, r.thermal, r.has_receiver ? &r.receiver : nullptr))
      throw std::invalid_argument(cf.path + ": " + p->key + ": " + p->message);
    allow_or_refuse(r, coupling::scale_down_validity(r.dem.scene.drum.diameter, r.dem.scene.particle.diameter),
                    o.allow_small_drum, "--allow-small-drum", cf.path);
    // 1. DEM, or its cached outputs.
    const auto t0 = std::chrono::steady_clock::now();
    // A DEM run hands its film over in memory (no write and read back of dem.h5 on the way);
    // a cached or given one is read back from its dem.h5.
    std::optional<io::DemRunResult> ran;
    if (!o.dem_from.empty()) {
      r.dem_given = true;
      r.dem_dir = o.dem_from;
      r.dem_summary = earlier_dem_run_summary(cf.resolved_yaml, o.dem_from);
    } else {
      r.cache_key = dem_cache_key(cf.resolved_yaml, r.dem, centrec::io::code_version());
      // A Ctrl-C while the DEM wrote its outputs stops the run once the cache holds them.
      std::optional<OutputsInterrupted> stopped;
      const CachedDem cached = cached_dem_run(o.cache_dir, r.cache_key, [&](const std::string& dir, bool resume) {
        if (resume) std::fprintf(stderr, "centrec run: continuing the interrupted DEM run in %s\n", dir.c_str());
        const auto from = resume ? std::optional<io::RunCheckpoint>(io::read_checkpoint(dir)) : std::nullopt;
        try {
          ran = run_dem_case(cf, r.dem, dir, native_engine(from));
        } catch (const OutputsInterrupted& e) {
          stopped = e;
        }
      });
      if (stopped) throw OutputsInterrupted(stopped->signal(), cached.dir);
      r.dem_dir = cached.dir;
      r.dem_cached = cached.hit;
      r.dem_resumed_from = cached.resumed_from;
      r.dem_summary = io::read_json_file(r.dem_dir + "/summary.json");
    }
    r.dem_seconds = since(t0);
    // 2. Mapping, scale-up, mass-flux conservation.
    const auto t1 = std::chrono::steady_clock::now();
    try {
      r.averages = ran ? coupling::dem_film_averages(ran->fields, r.dem.scene, ran->mass_flow,
                                                     r.dem.run.flow_window_turns, r.dem.run.steady_tolerance)
                       : io::read_dem_film(r.dem_dir + "/dem.h5", r.dem.scene, r.dem.run.flow_window_turns,
                                           r.dem.run.steady_tolerance);
    } catch (const std::exception& e) {
      // The usual cause: no film formed (too slow a drum for this retention, too short a run).
      const auto op = config::dem_operating_point(r.dem);
      throw std::runtime_error(std::string(e.what()) + "; the DEM drum ran at omega^2 R / g = " +
                               std::to_string(coupling::centrifugal_ratio(op)) + " and ended with a holdup of " +
                               std::to_string(r.dem_summary.value("holdup_kg", 0.0) * 1e3) + " g");
    }
    allow_or_refuse(r,
                    r.averages.steady
                        ? ""
                        : "the DEM film is not at steady flow: " + r.averages.steady_text +
                              " (tolerance run.steady_tolerance = " + std::to_string(r.dem.run.steady_tolerance) +
                              "; lengthen run.duration or run.max_extension)",
                    o.allow_unsteady, "--allow-unsteady", r.dem_dir);
    coupling::FilmMappingResult mapped = coupling::film_mapping(r.thermal.film_source.mapping).map(r.averages);
    r.mapping = std::move(mapped.report);
    thermal::FilmField film = std::move(mapped.film);
    // The flow the film carries, against the DEM's measured flow, at the DEM's scale.
    r.closure = coupling::flow_closure(film, r.averages.particle_density, r.averages.mdot);
    const double miss = r.closure.mean_over_measured - 1.0;
    allow_or_refuse(r,
                    std::abs(miss) <= coupling::kFlowClosureTolerance
                        ? ""
                        : "the mapped film carries " + std::to_string(100.0 * r.closure.mean_over_measured) +
                              " % of the DEM's measured flow (closure tolerance 5 %)",
                    o.allow_unsteady, "--allow-unsteady", r.dem_dir);
    // The case's flow: the receiver's, or the DEM's own target (feed or slice target).
    double mdot = dem::scene::target_mass_flow(r.dem.scene);
    if (r.has_receiver) {
      film = coupling::scale_up_film(film, config::dem_operating_point(r.dem), r.receiver.op, &r.scale);
      mdot = r.receiver.op.mass_flow;
    }
    r.imposed = coupling::impose_mass_flow(film, r.averages.particle_density, mdot);
    r.thermal.film = std::move(film);
    r.thermal.film_source.file = r.dem_dir + "/dem.h5";
    r.mapping_seconds = since(t1);
  }
  // 3. Thermal.
  const auto t2 = std::chrono::steady_clock::now();
  r.result = run_thermal_case(r.thermal);
  r.thermal_seconds = since(t2);
  return r;
}

}  // namespace centrec::runs
