#pragma once
// Bins of wall distance w = R - r of particle centres, of equal width given in particle
// diameters: bin k holds k * width <= w / d < (k + 1) * width. Shared by the velocity
// profile, solid fraction and dispersion samplers so their axes line up.
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::film {

struct WallDistanceBins {
  double width_d = 0.5;            // bin width in particle diameters
  int count = 16;                  // bins from the wall inward
  double particle_diameter = 0.0;  // d, m: the unit of the axis

  void check(const char* who) const {
    if (!(width_d > 0.0) || count < 1 || !(particle_diameter > 0.0))
      throw std::invalid_argument(std::string(who) + ": wall-distance bins need width > 0, count >= 1, d > 0");
  }
  double width_m() const { return width_d * particle_diameter; }
  // Bin of wall distance w (m), or -1 outside [0, count * width).
  int index(double w) const {
    const double k = std::floor(w / width_m());
    return (k < 0.0 || k >= count) ? -1 : static_cast<int>(k);
  }
  double centre_d(int k) const { return (k + 0.5) * width_d; }
  double lower_m(int k) const { return k * width_m(); }
  double upper_m(int k) const { return (k + 1) * width_m(); }
};

}  // namespace centrec::film
