#pragma once
// Mass of a sphere of the given density and radius.
#include <cmath>

namespace centrec::dem {

inline double sphere_mass(double density, double radius) {
  return density * (4.0 / 3.0) * M_PI * radius * radius * radius;
}

}  // namespace centrec::dem
