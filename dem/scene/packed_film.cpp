#include "dem/scene/packed_film.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::dem::scene {

std::vector<FilmSite> packed_film_sites(const std::vector<double>& radii, double R, double inset, double z0,
                                        double z1, bool periodic) {
  std::vector<FilmSite> out;
  if (radii.empty()) return out;
  const double dmax = 2.0 * *std::max_element(radii.begin(), radii.end());
  const double pitch = 1.02 * dmax;
  const double span = z1 - z0;
  const int n_z = static_cast<int>(std::floor(span / pitch));
  if (n_z < 1) throw std::invalid_argument("initial film: axial extent shorter than one particle");
  const double dz = periodic ? span / n_z : pitch;
  out.reserve(radii.size());
  std::size_t next = 0;
  for (int layer = 0; next < radii.size(); ++layer) {
    const double r = R - inset - 0.5 * dmax - layer * pitch;
    if (r < 2.0 * dmax)
      throw std::invalid_argument("initial film: " + std::to_string(radii.size()) +
                                  " particles do not fit in the drum");
    const int n_theta = static_cast<int>(std::floor(2.0 * M_PI * r / pitch));
    const double dth = 2.0 * M_PI / n_theta;
    // Stagger alternate layers so they nest instead of stacking column on column.
    const double shift = (layer % 2) ? 0.5 * dth : 0.0;
    const double zshift = (layer % 2) ? 0.5 * dz : 0.0;
    for (int k = 0; k < n_z && next < radii.size(); ++k) {
      double z = z0 + 0.5 * dz + k * dz + zshift;
      if (periodic) z = z0 + std::fmod(z - z0, span);
      else if (z + 0.5 * dmax > z1) continue;
      for (int j = 0; j < n_theta && next < radii.size(); ++j) {
        const double th = j * dth + shift;
        out.push_back({{r * std::cos(th), r * std::sin(th), z}, radii[next]});
        ++next;
      }
    }
  }
  return out;
}

}  // namespace centrec::dem::scene
