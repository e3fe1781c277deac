#pragma once
// Reads the averaged film of a DEM run back from DIR/dem.h5 (written by
// apps/io/dem_output_h5): the film fields and the mass-flow record, turned into the
// coupling's DemFilmAverages by the same coupling::dem_film_averages that a run just made
// in memory uses, so a cached DEM gives the coupling the same numbers as a fresh one.
#include <string>

#include "coupling/dem_film_averages.hpp"
#include "dem/scene/scene_config.hpp"

namespace centrec::io {

// Throws std::runtime_error naming the file and the missing or inconsistent item.
coupling::DemFilmAverages read_dem_film(const std::string& path, const dem::scene::SceneConfig& scene,
                                        double flow_window_turns, double steady_tolerance);

}  // namespace centrec::io
