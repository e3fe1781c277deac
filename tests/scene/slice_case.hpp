#pragma once
// The small periodic slice the controller tests share: D/d = 25 at the scaled quickstart
// speed, a 4 d slice on the rough wall, 2 threads.
#include <cmath>
#include <cstdint>

#include "dem/scene/scene_config.hpp"

namespace centrec::testing {

inline dem::scene::SceneConfig controlled_slice(std::int64_t particles, double target_mass_flow) {
  dem::scene::SceneConfig c;
  c.drum.diameter = 0.03;
  c.drum.omega = 320.16 * 2 * M_PI / 60;
  c.rough_wall.enabled = true;
  c.slice.enabled = true;
  c.slice.length = 4 * c.particle.diameter;
  c.slice.target_mass_flow = target_mass_flow;
  c.initial_film.particles = particles;
  c.dt = 2e-5;
  c.threads = 2;
  return c;
}

}  // namespace centrec::testing
