#pragma once
// Reads the averaged film fields of a DEM run (DIR/dem.h5 /film, written by
// apps/io/dem_output_h5) into the coupling's plain DemFilmAverages. The drum's length, speed
// and particle density come from the scene that made the file; the outlet mass flow is
// measured from /mass_flow over the run's flow window (run.flow_window_turns).
#include <string>

#include "coupling/dem_film_averages.hpp"
#include "dem/scene/scene_config.hpp"

namespace centrec::io {

// Throws std::runtime_error naming the file and the missing or inconsistent item.
coupling::DemFilmAverages read_dem_film(const std::string& path, const dem::scene::SceneConfig& scene,
                                        double flow_window_turns);

}  // namespace centrec::io
