#pragma once
// The DEM's averaged film as the coupling reads it, taken from what the DEM run produced:
// the samplers' film fields, the mass-flow log and the scene. This is the hand-off from the
// DEM to the film field; dem.h5 stores the same numbers, and a cached run reads them back
// into the same two inputs (apps/io/dem_film_h5), so both give the same averages.
#include <vector>

#include "coupling/dem_film_averages.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_config.hpp"
#include "dem/scene/scene_sampler.hpp"

namespace centrec::coupling {

// flow_window_turns, steady_tolerance: the window over which the measured flow is averaged
// and the tolerance of its steadiness (run.flow_window_turns, run.steady_tolerance).
// Throws std::invalid_argument naming the first missing or inconsistent item.
DemFilmAverages dem_film_averages(const dem::scene::SampledFilm& fields, const dem::scene::SceneConfig& scene,
                                  const std::vector<dem::scene::MassFlowSample>& mass_flow, double flow_window_turns,
                                  double steady_tolerance);

}  // namespace centrec::coupling
