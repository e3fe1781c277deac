#include "dem/scene/packed_film.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dem/scene/size_distribution.hpp"

namespace centrec::dem::scene {

namespace {

// Walks the lattice's sites in placement order (layers from the wall inward, each layer's
// axial rows, each row's angles) until `limit` sites or the layers run out (a layer nearer
// the axis than two diameters); returns how many it visited.
template <class Visit>
std::size_t walk_sites(double dmax, double R, double inset, double z0, double z1, bool periodic, std::size_t limit,
                       Visit visit) {
  const double pitch = 1.02 * dmax;
  const double span = z1 - z0;
  const int n_z = static_cast<int>(std::floor(span / pitch));
  if (n_z < 1) return 0;
  const double dz = periodic ? span / n_z : pitch;
  std::size_t next = 0;
  for (int layer = 0; next < limit; ++layer) {
    const double r = R - inset - 0.5 * dmax - layer * pitch;
    if (r < 2.0 * dmax) break;
    const int n_theta = static_cast<int>(std::floor(2.0 * M_PI * r / pitch));
    const double dth = 2.0 * M_PI / n_theta;
    // Stagger alternate layers so they nest instead of stacking column on column.
    const double shift = (layer % 2) ? 0.5 * dth : 0.0;
    const double zshift = (layer % 2) ? 0.5 * dz : 0.0;
    for (int k = 0; k < n_z && next < limit; ++k) {
      double z = z0 + 0.5 * dz + k * dz + zshift;
      if (periodic) z = z0 + std::fmod(z - z0, span);
      else if (z + 0.5 * dmax > z1) continue;
      for (int j = 0; j < n_theta && next < limit; ++j) {
        const double th = j * dth + shift;
        visit(Vec3{r * std::cos(th), r * std::sin(th), z}, next);
        ++next;
      }
    }
  }
  return next;
}

}  // namespace

std::size_t packed_film_capacity(double dmax, double R, double inset, double z0, double z1, bool periodic) {
  return walk_sites(dmax, R, inset, z0, z1, periodic, static_cast<std::size_t>(-1), [](const Vec3&, std::size_t) {});
}

std::vector<FilmSite> packed_film_sites(const std::vector<double>& radii, double R, double inset, double z0,
                                        double z1, bool periodic) {
  std::vector<FilmSite> out;
  if (radii.empty()) return out;
  const double dmax = 2.0 * *std::max_element(radii.begin(), radii.end());
  if (std::floor((z1 - z0) / (1.02 * dmax)) < 1)
    throw std::invalid_argument("initial film: axial extent shorter than one particle");
  out.reserve(radii.size());
  const std::size_t placed = walk_sites(dmax, R, inset, z0, z1, periodic, radii.size(),
                                        [&](const Vec3& x, std::size_t i) { out.push_back({x, radii[i]}); });
  if (placed < radii.size())
    throw std::invalid_argument("initial film: " + std::to_string(radii.size()) +
                                " particles do not fit in the drum (at most " + std::to_string(placed) + ")");
  return out;
}

LooseFilmRegion loose_film_region(const SceneConfig& c) {
  LooseFilmRegion g;
  g.R = 0.5 * c.drum.diameter;
  g.periodic = c.slice.enabled;
  const double zmax = g.periodic ? c.slice.length : c.drum.length;
  g.inset = c.rough_wall.enabled ? c.rough_wall.sphere_diameter : 0.0;
  g.z0 = g.periodic ? 0.0 : c.initial_film.axial_from;
  g.z1 = g.periodic ? zmax : (c.initial_film.axial_to > 0.0 ? c.initial_film.axial_to : zmax);
  return g;
}

std::vector<double> loose_film_radii(const SceneConfig& c) {
  SizeSampler sizes(c.particle, c.seed + 1);
  std::vector<double> radii(static_cast<std::size_t>(c.initial_film.particles));
  for (double& r : radii) r = 0.5 * sizes.next_diameter();
  return radii;
}

std::size_t loose_film_capacity(const SceneConfig& c, std::size_t count) {
  const LooseFilmRegion g = loose_film_region(c);
  auto capacity = [&](double dmax) { return packed_film_capacity(dmax, g.R, g.inset, g.z0, g.z1, g.periodic); };
  // The lattice's pitch follows the largest sphere drawn: bounded by the distribution's
  // extremes, so the draw is needed only between them.
  const SizeSampler sizes(c.particle, c.seed + 1);
  const std::size_t least = capacity(sizes.max_diameter());
  if (count <= least || c.particle.distribution == SizeDistribution::mono) return least;
  const std::size_t most = capacity(sizes.min_diameter());
  if (count > most) return most;
  const std::vector<double> radii = loose_film_radii(c);
  return capacity(2.0 * *std::max_element(radii.begin(), radii.end()));
}

}  // namespace centrec::dem::scene
