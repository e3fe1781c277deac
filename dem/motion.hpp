#pragma once
// Per-particle motion flag and the drum rotation that carries glued particles.
#include <cstdint>

#include "dem/vec3.hpp"

namespace centrec::dem {

// How a particle moves.
enum class Motion : std::uint8_t {
  free,  // integrated (velocity Verlet)
  drum,  // moved rigidly with the drum about SimulationConfig::drum (glued rough-wall layer)
};

// Rigid rotation of the drum: carries Motion::drum particles. Walls carry their own
// angular velocity (Wall::cylinder/disc omega); give them the same omega for a drum.
struct DrumMotion {
  Vec3 origin;         // a point on the axis
  Vec3 axis{0, 0, 1};  // unit
  double omega = 0.0;  // rad/s, right-handed about axis
};

}  // namespace centrec::dem
