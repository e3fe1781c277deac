#pragma once
// The starting film: a loose lattice of spheres on the drum's inside, co-rotating
// rigidly with it, layer by layer from the wall inward until the count is reached.
#include <cstdint>
#include <vector>

#include "dem/vec3.hpp"

namespace centrec::dem::scene {

struct FilmSite {
  Vec3 x;
  double radius;
};

// `count` sites for spheres of the given radii (one per site, in order) between z0 and z1
// inside a wall of radius R, starting at wall distance `inset` (a rough wall's height).
// Lattice pitch 1.02 x the largest diameter; with `periodic` the axial pitch tiles z1-z0.
// Throws std::invalid_argument if the film would reach the drum axis.
std::vector<FilmSite> packed_film_sites(const std::vector<double>& radii, double R, double inset, double z0,
                                        double z1, bool periodic);

}  // namespace centrec::dem::scene
