#pragma once
// Solid fraction of the glued rough-wall monolayer (docs/centrec_scene.md) per wall-distance
// bin. The DEM's solid-fraction sampler sees only the free particles, but the glued spheres
// are part of the film the heat crosses (the film thickness of eqs 4-7 counts from the
// wall), so the mapping adds them back. Planar approximation (sphere << drum radius): a
// sphere of diameter s touching the wall fills, between wall distances a and b, the volume
// V(b) - V(a) with V(h) = pi h^2 (3 s/2 - h) / 3 (h clamped to [0, s]).
#include <vector>

#include "dem/scene/scene_config.hpp"

namespace centrec::coupling {

// bins: centres in d, equal width in d; spheres_per_area: glued spheres per m2 of wall.
std::vector<double> glued_layer_solid_fraction(const std::vector<double>& centres_d, double bin_width_d,
                                               double particle_diameter, double sphere_diameter,
                                               double spheres_per_area);

// The same for the scene's own rough wall (its glued spheres counted on the scene's lattice
// over the drum, or the slice, of radius drum_radius); empty without a rough wall.
std::vector<double> glued_layer_solid_fraction(const dem::scene::SceneConfig& scene, double drum_radius,
                                               const std::vector<double>& centres_d, double bin_width_d,
                                               double particle_diameter);

}  // namespace centrec::coupling
