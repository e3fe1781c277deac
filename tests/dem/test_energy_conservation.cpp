// (d) e = 1, mu = 0, mu_r = 0: kinetic + rotational + gravitational + Hertz elastic energy
// (8/15) E* sqrt(R*) delta^(5/2) per contact is conserved within 1e-4 (relative) over 1e5
// steps, for a few spheres bouncing off each other and the six walls of a box.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

constexpr double kBox = 5e-3;

double hertz_energy(double E_eff, double r_eff, double delta) {
  return delta > 0.0 ? (8.0 / 15.0) * E_eff * std::sqrt(r_eff) * std::pow(delta, 2.5) : 0.0;
}

double total_energy(const Simulation& sim, Vec3 g) {
  const Material m = paper_material();
  const double E = m.youngs_modulus / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
  double e = 0.0;
  const auto& x = sim.positions();
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const double mass = sim.masses()[i], r = sim.radii()[i];
    e += 0.5 * mass * norm2(sim.velocities()[i]) + 0.2 * mass * r * r * norm2(sim.angular_velocities()[i]);
    e -= mass * dot(g, x[i]);
    for (std::size_t j = i + 1; j < sim.size(); ++j)
      e += hertz_energy(E, r * sim.radii()[j] / (r + sim.radii()[j]), r + sim.radii()[j] - norm(x[i] - x[j]));
    for (double c : {x[i].x, x[i].y, x[i].z, kBox - x[i].x, kBox - x[i].y, kBox - x[i].z})
      e += hertz_energy(E, r, r - c);
  }
  return e;
}

}  // namespace

TEST(EnergyConservation, ElasticFrictionlessBoxConservesEnergy) {
  const Vec3 g{0, 0, -9.81};
  Simulation sim(quiet_config(1e-6, g));  // about t_c / 200 at these speeds (2e-6 gives 5.4e-5)
  const MaterialId grain = use_paper_material(sim, PairInteraction{1.0, 0.0, 0.0});
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
    sim.add_wall(Wall::plane({0, 0, 0}, n, grain));
    sim.add_wall(Wall::plane({kBox, kBox, kBox}, -n, grain));
  }
  const Vec3 starts[] = {{1.2e-3, 1.3e-3, 1.5e-3}, {3.6e-3, 1.1e-3, 2.5e-3}, {2.4e-3, 3.7e-3, 3.6e-3},
                         {1.1e-3, 3.5e-3, 2.2e-3}};
  const Vec3 vels[] = {{0.3, 0.1, -0.2}, {-0.2, 0.25, 0.1}, {0.1, -0.3, 0.2}, {0.2, -0.1, -0.3}};
  for (int k = 0; k < 4; ++k) sim.add_particle({grain, kRadius, starts[k], vels[k], {100.0 * k, -50.0, 30.0}});
  sim.setup();
  const double e0 = total_energy(sim, g);
  double worst = 0.0;
  std::size_t contact_steps = 0;
  for (int s = 0; s < 100000; ++s) {
    sim.step(1);
    const auto st = sim.neighbour_stats();
    contact_steps += st.pair_contacts + st.wall_contacts > 0;
    if (s % 10 == 0 || st.pair_contacts + st.wall_contacts > 0)
      worst = std::max(worst, std::fabs(total_energy(sim, g) / e0 - 1.0));
  }
  std::printf("(d) 4 spheres, 1e5 steps (%zu with contacts): max |E/E0 - 1| = %.3e (tolerance 1e-4)\n",
              contact_steps, worst);
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(contact_steps, 1000u);  // the run must actually exercise contacts
}
