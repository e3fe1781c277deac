#pragma once
// Outputs of `centrec run`: DIR/results.h5 + DIR/results.xmf (the thermal groups of
// thermal.h5, the coupled film /film, and /coupling: mapping and scaling records),
// DIR/film.h5 (the film field alone, reusable as `film: {file: DIR/film.h5}`) and
// DIR/summary.json (outlet temperature, efficiency, k_eff and its parts, film thickness,
// mdot, scaling, wall time per stage).
#include <nlohmann/json.hpp>
#include <string>

#include "io/provenance.hpp"
#include "runs/coupled_run.hpp"

namespace centrec::runs {

// DIR/results.h5 with DIR/results.xmf, and DIR/film.h5; p: the case's provenance.
void write_coupled_h5(const std::string& dir, const CoupledRun& r, const io::Provenance& p);
nlohmann::json coupled_summary(const CoupledRun& r);

// The coupled film's thickness over its sections, in particle diameters.
struct FilmThickness {
  double mean_m = 0.0, mean_d = 0.0, min_d = 0.0, max_d = 0.0;
};
FilmThickness film_thickness(const CoupledRun& r);

}  // namespace centrec::runs
