// Analytic wall geometry (plane, cylinder interior with axial extent, annular plate with
// both faces and its inner rim) and particles glued to the turning drum (Motion::drum).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

TEST(Walls, GeometryOfPlaneCylinderAndAnnulus) {
  const MaterialId grain(0);  // geometry only: no engine
  double dist;
  Vec3 n, p;
  const Wall plane = Wall::plane({0, 0, 1}, {0, 0, 2}, grain);
  ASSERT_TRUE(wall_geometry(plane, {3, 4, 1.5}, dist, n, p));
  EXPECT_DOUBLE_EQ(dist, 0.5);
  EXPECT_EQ(n, (Vec3{0, 0, 1}));
  EXPECT_FALSE(wall_geometry(plane, {0, 0, 0.5}, dist, n, p));  // behind: one-sided

  const Wall cyl = Wall::cylinder({0, 0, 0}, {0, 0, 1}, 0.06, 0.0, 0.1, 10.0, grain);
  ASSERT_TRUE(wall_geometry(cyl, {0.05, 0, 0.05}, dist, n, p));
  EXPECT_NEAR(dist, 0.01, 1e-15);
  EXPECT_EQ(n, (Vec3{-1, 0, 0}));
  EXPECT_NEAR(norm(p - Vec3{0.06, 0, 0.05}), 0.0, 1e-15);
  EXPECT_NEAR(norm(wall_velocity_at(cyl, p) - Vec3{0, 0.6, 0}), 0.0, 1e-15);  // omega x r
  EXPECT_FALSE(wall_geometry(cyl, {0.05, 0, 0.2}, dist, n, p));              // beyond the axial extent

  // Annular weir of inner radius 0.05 in the plane z = 0.1.
  const Wall lip = Wall::disc({0, 0, 0.1}, {0, 0, 1}, 0.06, 0.05, 10.0, grain);
  ASSERT_TRUE(wall_geometry(lip, {0.055, 0, 0.099}, dist, n, p));  // on the face, from below
  EXPECT_NEAR(dist, 0.001, 1e-15);
  EXPECT_NEAR(n.z, -1.0, 1e-15);
  ASSERT_TRUE(wall_geometry(lip, {0.049, 0, 0.1005}, dist, n, p));  // over the inner rim
  EXPECT_NEAR(dist, std::hypot(0.001, 0.0005), 1e-15);
  EXPECT_NEAR(norm(p - Vec3{0.05, 0, 0.1}), 0.0, 1e-15);
  EXPECT_THROW(check_wall(Wall::disc({0, 0, 0}, {0, 0, 1}, 0.05, 0.06, 0.0, grain)), std::invalid_argument);
}

TEST(Walls, ParticleBouncesOffAnnulusFaceAndFallsThroughItsHole) {
  Simulation sim(quiet_config(paper_contact_time(1.0, true) / 200.0));
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.9, 0.0, 0.0});
  const int lip = sim.add_wall(Wall::disc({0, 0, 0}, {0, 0, 1}, 0.06, 0.05, 0.0, grain));
  // Falling onto the face (inside the annulus) and onto the hole (misses the plate).
  const std::int64_t hit = sim.add_particle({grain, kRadius, {0.055, 0, 2 * kRadius}, {0, 0, -1.0}, {}});
  const std::int64_t miss = sim.add_particle({grain, kRadius, {0.0, 0, 2 * kRadius}, {0, 0, -1.0}, {}});
  double peak = 0.0;
  for (int s = 0; s < 800; ++s) {
    sim.step(1);
    peak = std::max(peak, std::fabs(sim.wall_force(lip).z));
  }
  const double vz_hit = sim.velocities()[static_cast<std::size_t>(sim.index_of(hit))].z;
  const double vz_miss = sim.velocities()[static_cast<std::size_t>(sim.index_of(miss))].z;
  std::printf("annulus: rebound on the face %.4f m/s (e = 0.9 expected, tolerance 1 %%), through the hole %.4f m/s, "
              "peak plate force %.3e N\n",
              vz_hit, vz_miss, peak);
  EXPECT_NEAR(vz_hit / 0.9, 1.0, 0.01);
  EXPECT_NEAR(vz_miss, -1.0, 1e-9);
  EXPECT_GT(peak, 0.0);
}

TEST(Walls, GluedParticlesTurnRigidlyWithTheDrum) {
  SimulationConfig cfg = quiet_config(1e-5, {0, -9.81, 0});
  cfg.drum.omega = 160.08 * 2 * M_PI / 60;
  Simulation sim(cfg);
  const MaterialId grain = use_paper_material(sim, PairInteraction{});
  const Vec3 x0{0.0594, 0.0, 0.01};
  sim.add_particle({grain, kRadius, x0, {}, {}, Motion::drum});
  const long steps = std::lround(2 * M_PI / cfg.drum.omega / 1e-5);  // ~ one turn
  sim.step(steps);
  const double angle = cfg.drum.omega * 1e-5 * static_cast<double>(steps);
  const Vec3 expected{0.0594 * std::cos(angle), 0.0594 * std::sin(angle), 0.01};
  const Vec3 x = sim.positions()[0], v = sim.velocities()[0];
  std::printf("glued particle after %ld steps: position error %.2e m, |v| = %.5f m/s (omega r = %.5f)\n", steps,
              norm(x - expected), norm(v), cfg.drum.omega * 0.0594);
  EXPECT_LT(norm(x - expected), 1e-9);
  EXPECT_NEAR(norm(v), cfg.drum.omega * 0.0594, 1e-9);
  EXPECT_EQ(sim.angular_velocities()[0], (Vec3{0, 0, cfg.drum.omega}));
}
