#pragma once
#include <cmath>

namespace centrec::dem::scene {

inline double sphere_mass(double density, double radius) {
  return density * 4.0 / 3.0 * M_PI * radius * radius * radius;
}

}  // namespace centrec::dem::scene
