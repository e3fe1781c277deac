#pragma once
// The starting film: a loose lattice of spheres on the drum's inside, co-rotating
// rigidly with it, layer by layer from the wall inward until the count is reached.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem::scene {

struct FilmSite {
  Vec3 x;
  double radius;
};

// Where a scene lays its loose film (dem.initial_film.particles): inside the wall of radius
// R from wall distance `inset` (a rough wall's height), between z0 and z1 (a slice: its
// whole period, tiled).
struct LooseFilmRegion {
  double R = 0.0, inset = 0.0, z0 = 0.0, z1 = 0.0;
  bool periodic = false;
};
LooseFilmRegion loose_film_region(const SceneConfig& c);

// `count` sites for spheres of the given radii (one per site, in order) between z0 and z1
// inside a wall of radius R, starting at wall distance `inset` (a rough wall's height).
// Lattice pitch 1.02 x the largest diameter; with `periodic` the axial pitch tiles z1-z0.
// Throws std::invalid_argument if the film would reach the drum axis.
std::vector<FilmSite> packed_film_sites(const std::vector<double>& radii, double R, double inset, double z0,
                                        double z1, bool periodic);

// How many spheres of largest diameter dmax packed_film_sites places at most (0 where the
// axial extent is shorter than one lattice pitch).
std::size_t packed_film_capacity(double dmax, double R, double inset, double z0, double z1, bool periodic);

// The radii of the loose film's dem.initial_film.particles spheres, drawn as the scene draws
// them (seed + 1).
std::vector<double> loose_film_radii(const SceneConfig& c);
// How many of the case's loose film spheres the scene's lattice holds; exact whenever `count`
// exceeds it (validate refuses what the scene would).
std::size_t loose_film_capacity(const SceneConfig& c, std::size_t count);

}  // namespace centrec::dem::scene
