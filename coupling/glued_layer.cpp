#include "glued_layer.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace centrec::coupling
