#include "glued_layer.hpp"

#include <algorithm>
#include <cmath>

#include "dem/scene/wall_lattice.hpp"

namespace centrec::coupling {

std::vector<double> glued_layer_solid_fraction(const std::vector<double>& centres_d, double bin_width_d,
                                               double particle_diameter, double sphere_diameter,
                                               double spheres_per_area) {
  const double s = sphere_diameter, r = 0.5 * s;
  auto cap = [&](double h) {
    h = std::clamp(h, 0.0, s);
    return M_PI * h * h * (3.0 * r - h) / 3.0;
  };
  std::vector<double> phi;
  for (double c : centres_d) {
    const double a = (c - 0.5 * bin_width_d) * particle_diameter, b = (c + 0.5 * bin_width_d) * particle_diameter;
    phi.push_back(spheres_per_area * (cap(b) - cap(a)) / (b - a));
  }
  return phi;
}

std::vector<double> glued_layer_solid_fraction(const dem::scene::SceneConfig& scene, double drum_radius,
                                               const std::vector<double>& centres_d, double bin_width_d,
                                               double particle_diameter) {
  const auto& rough = scene.rough_wall;
  if (!rough.enabled) return {};
  const bool slice = scene.slice.enabled;
  const double len = slice ? scene.slice.length : scene.drum.length;
  const double n =
      static_cast<double>(dem::scene::rough_wall_centres(rough, drum_radius, 0.0, len, slice).size());
  return glued_layer_solid_fraction(centres_d, bin_width_d, particle_diameter, rough.sphere_diameter,
                                    n / (2.0 * M_PI * drum_radius * len));
}

}  // namespace centrec::coupling
