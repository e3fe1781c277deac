#pragma once
// A dense film of the paper's particles (Table 1) on the inside of a drum of D = 0.12 m
// turning at 160 rpm with wall friction 10000 (paper case D12), axis along z and gravity
// tilted 45 deg to it. Used by the speed probe and the determinism test.
#include <cmath>
#include <cstdint>

#include "dem/simulation.hpp"

namespace centrec::dem::testing {

struct FilmScene {
  double drum_radius = 0.06;
  double rpm = 160.08;
  double length = 0.0;  // axial length, chosen from N when 0
  double dt = 1e-5;
  int threads = 1;
  bool periodic = false;
};

inline double film_omega(const FilmScene& s) { return s.rpm * 2.0 * M_PI / 60.0; }

// Builds the drum (cylinder + two end plates, all co-rotating) and n particles on rings
// near the wall, co-rotating, barely apart. Settle it with sim.step() before measuring.
inline void build_film(Simulation& sim, const FilmScene& s, std::size_t n) {
  const double d = 1.2e-3, omega = film_omega(s);
  const double length = s.length > 0.0 ? s.length : std::max(20 * d, n * d * d * d / (0.55 * 2 * M_PI * s.drum_radius * 6 * d));
  const MaterialId grain = sim.add_material(Material{5e6, 0.3, 3560.0});
  sim.set_interaction(grain, grain, PairInteraction{0.46, 0.81, 0.26});
  const MaterialId wall_mat = sim.add_material(Material{5e6, 0.3, 3560.0});
  sim.set_interaction(grain, wall_mat, PairInteraction{0.46, 10000.0, 0.26});
  sim.add_wall(Wall::cylinder({0, 0, 0}, {0, 0, 1}, s.drum_radius, -1.0, length + 1.0, omega, wall_mat));
  if (!s.periodic) {
    sim.add_wall(Wall::disc({0, 0, 0}, {0, 0, 1}, s.drum_radius, 0.0, omega, wall_mat));
    sim.add_wall(Wall::disc({0, 0, length}, {0, 0, 1}, s.drum_radius, 0.0, omega, wall_mat));
  }
  const double pitch = 1.001 * d;  // barely apart: the film closes up within a few ms
  std::size_t placed = 0;
  for (int layer = 0; placed < n; ++layer) {
    const double r = s.drum_radius - 0.5 * d - 1e-5 - layer * pitch;
    const int around = static_cast<int>(2 * M_PI * r / pitch);
    const int along = static_cast<int>((length - d) / pitch);
    for (int k = 0; k < along && placed < n; ++k) {
      for (int a = 0; a < around && placed < n; ++a, ++placed) {
        const double phi = 2 * M_PI * (a + 0.5 * (k % 2)) / around;
        const Vec3 x{r * std::cos(phi), r * std::sin(phi), 0.5 * d + 1e-5 + k * pitch};
        sim.add_particle({grain, 0.5 * d, x, {-omega * x.y, omega * x.x, 0.0}, {0, 0, omega}});
      }
    }
  }
}

inline SimulationConfig film_config(const FilmScene& s) {
  SimulationConfig c;
  c.dt = s.dt;
  c.gravity = {0.0, -9.81 * std::sqrt(0.5), -9.81 * std::sqrt(0.5)};
  c.threads = s.threads;
  c.drum.omega = film_omega(s);
  c.max_impact_speed = 1.0;
  return c;
}

}  // namespace centrec::dem::testing
