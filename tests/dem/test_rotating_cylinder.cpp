// (f) Particles in a cylinder rotating at 160 rpm (D = 0.12 m) with wall friction 10000
// reach rigid co-rotation: v = Omega x r and spin = Omega (default, relative wall rolling).
// With the LIGGGHTS-compatible switch the EPSD2 wall spring sees the absolute spin, so the
// spurious torque (docs/dem_physics.md) brakes the particles' spin towards zero while the
// wall still carries them round: they co-rotate in position but do not spin with the drum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

struct CoRotation {
  double worst_velocity;  // max |v - Omega x r| / (Omega R)
  double worst_spin;      // max |w - Omega| / Omega
  double mean_roll_ratio;  // mean |M_r| / (mu_r R |Fn|) over particles touching the wall
};

CoRotation spin_up(WallRolling mode) {
  const double R = 0.06, omega = 160.08 * 2 * M_PI / 60, mu_r = 0.26;
  SimulationConfig cfg = quiet_config(1e-5, {0, 0, 0});
  cfg.wall_rolling = mode;
  Simulation sim(cfg);
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.46, 0.81, mu_r});
  const MaterialId wall_mat = sim.add_material(paper_material());
  sim.set_interaction(grain, wall_mat, PairInteraction{0.46, 10000.0, mu_r});
  const int drum = sim.add_wall(Wall::cylinder({0, 0, 0}, {0, 0, 1}, R, -1.0, 1.0, omega, wall_mat));
  // Particles touching the wall, lagging it by 30 % and not spinning (as fed particles
  // arrive); their centrifugal load presses them on the wall, whose friction drags them along.
  // (At rest they would only spin in place: no normal load, no grip.)
  const int n = 24;
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * M_PI * k / n, rho = R - kRadius;
    const Vec3 x{rho * std::cos(phi), rho * std::sin(phi), 1e-3 * (k % 3)};
    sim.add_particle({grain, kRadius, x, {-0.7 * omega * x.y, 0.7 * omega * x.x, 0.0}, {}});
  }
  sim.step(40000);  // 0.4 s, about one turn
  CoRotation out{0, 0, 0};
  int touching = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const Vec3 x = sim.positions()[i];
    const Vec3 rigid{-omega * x.y, omega * x.x, 0.0};
    out.worst_velocity = std::max(out.worst_velocity, norm(sim.velocities()[i] - rigid) / (omega * R));
    out.worst_spin = std::max(out.worst_spin, norm(sim.angular_velocities()[i] - Vec3{0, 0, omega}) / omega);
    const double rho = std::hypot(x.x, x.y), delta = rho + kRadius - R;
    if (delta > 0) {
      const double fn = (4.0 / 3.0) * 5e6 / (2 * (1 - 0.09)) * std::sqrt(kRadius) * std::pow(delta, 1.5);
      out.mean_roll_ratio += norm(sim.wall_history(i, drum).roll) / (mu_r * kRadius * fn);
      ++touching;
    }
  }
  if (touching) out.mean_roll_ratio /= touching;
  EXPECT_EQ(touching, n);
  return out;
}

}  // namespace

TEST(RotatingCylinder, WallFrictionGivesRigidCoRotation) {
  const CoRotation rel = spin_up(WallRolling::relative);
  std::printf("(f) relative wall rolling: max |v - Omega x r|/(Omega R) = %.2e, max |w - Omega|/Omega = %.2e "
              "(tolerance 1e-2), wall rolling torque / limit = %.3f\n",
              rel.worst_velocity, rel.worst_spin, rel.mean_roll_ratio);
  EXPECT_LT(rel.worst_velocity, 1e-2);
  EXPECT_LT(rel.worst_spin, 1e-2);
  EXPECT_LT(rel.mean_roll_ratio, 0.05);

  const CoRotation lig = spin_up(WallRolling::liggghts);
  std::printf("(f) liggghts wall rolling: max |v - Omega x r|/(Omega R) = %.2e (the wall still carries them), "
              "max |w - Omega|/Omega = %.2f (spin braked by the spurious torque)\n",
              lig.worst_velocity, lig.worst_spin);
  EXPECT_LT(lig.worst_velocity, 2e-2);
  EXPECT_GT(lig.worst_spin, 0.5);
}
