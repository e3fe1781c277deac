// (e) A bed settled in a box: the bottom wall carries the bed's weight within 0.5 %.
// Side walls are frictionless (their forces are horizontal), so the bed's weight has
// nowhere else to go once the bed is at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

TEST(BedWeight, BottomWallCarriesTheWeight) {
  const Vec3 g{0, 0, -9.81};
  Simulation sim(quiet_config(0.0, g));  // dt: the advisor's default
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.2, 0.5, 0.1});
  const MaterialId smooth = sim.add_material(paper_material());
  sim.set_interaction(grain, smooth, PairInteraction{0.2, 0.0, 0.0});
  const double side = 8e-3;
  const int bottom = sim.add_wall(Wall::plane({0, 0, 0}, {0, 0, 1}, grain));
  sim.add_wall(Wall::plane({0, 0, 0}, {1, 0, 0}, smooth));
  sim.add_wall(Wall::plane({side, 0, 0}, {-1, 0, 0}, smooth));
  sim.add_wall(Wall::plane({0, 0, 0}, {0, 1, 0}, smooth));
  sim.add_wall(Wall::plane({0, side, 0}, {0, -1, 0}, smooth));
  double weight = 0.0;
  const double pitch = 1.25e-3;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) {
        // Slightly uneven radii and a shifted lattice so the bed does not crystallise.
        const double r = kRadius * (0.92 + 0.08 * ((i * 7 + j * 3 + k * 5) % 5) / 4.0);
        sim.add_particle({grain, r, {0.7e-3 + i * pitch + 0.1e-3 * (k % 2), 0.7e-3 + j * pitch, 0.7e-3 + k * pitch}, {}, {}});
        weight += sphere_mass(r) * 9.81;
      }
  sim.step(30000);  // settle (~0.25 s)
  Vec3 mean{};
  const int window = 5000;
  for (int s = 0; s < window; ++s) {
    sim.step(1);
    mean += (1.0 / window) * sim.wall_force(bottom);
  }
  double ke = 0.0;
  for (std::size_t i = 0; i < sim.size(); ++i) ke += 0.5 * sim.masses()[i] * norm2(sim.velocities()[i]);
  std::printf("(e) %zu particles settled in a box: bottom-wall force %.6e N, weight %.6e N (error %+.4f %%, "
              "tolerance 0.5 %%), kinetic energy left %.2e J\n",
              sim.size(), -mean.z, weight, 100.0 * (-mean.z / weight - 1.0), ke);
  EXPECT_NEAR(-mean.z / weight, 1.0, 0.005);
}
