#pragma once
// Positions of the glued rough-wall monolayer (docs/centrec_scene.md): spheres touching
// the drum wall on a square or hexagonal lattice in (arc length, z).
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem::scene {

// Centres of the glued spheres on a wall of radius R over z in [z0, z1). With `periodic`
// the axial count is rounded so the lattice tiles the period exactly.
std::vector<Vec3> rough_wall_centres(const RoughWallSpec& spec, double R, double z0, double z1, bool periodic);

}  // namespace centrec::dem::scene
