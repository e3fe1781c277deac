// The retention study's scene options in the full drum and in the
// periodic slice: size spread (packed start and feeder), rough wall (glued, co-rotating),
// outlet lip (holds a film below its height; refused in a slice, which has no outlet) and
// the wall rolling model (reaches the engine in both modes).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/scene/centrec_scene.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

namespace {

SceneConfig small(bool slice) {
  SceneConfig c;
  c.drum.diameter = 0.03;
  c.drum.length = 0.02;
  c.drum.omega = 320.16 * 2 * M_PI / 60;
  c.slice.enabled = slice;
  c.slice.length = 8 * c.particle.diameter;
  c.feeder.mass_flow = 8.925e-3;
  c.dt = 2e-5;
  c.threads = 1;
  return c;
}

struct RadiusStats {
  double mean = 0, rel_std = 0, lo = 1e9, hi = 0;
  std::size_t n = 0;
};

RadiusStats free_radii(const Simulation& sim) {
  RadiusStats s;
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (sim.motions()[i] != Motion::free) continue;
    const double r = sim.radii()[i];
    sum += r, sum2 += r * r, ++s.n;
    s.lo = std::min(s.lo, r), s.hi = std::max(s.hi, r);
  }
  s.mean = sum / s.n;
  s.rel_std = std::sqrt(std::max(0.0, sum2 / s.n - s.mean * s.mean)) / s.mean;
  return s;
}

}  // namespace

TEST(RetentionOptions, SizeSpreadInPackedStartAndFeeder) {
  for (bool slice : {false, true}) {
    for (SizeDistribution dist : {SizeDistribution::uniform, SizeDistribution::normal}) {
      SceneConfig c = small(slice);
      c.particle.distribution = dist;
      c.particle.relative_spread = dist == SizeDistribution::uniform ? 0.10 : 0.05;
      c.initial_film.particles = 1500;
      CentrecScene s(c);
      s.advance(0.03);  // the drum's feeder inserts ~80 more particles from the same distribution
      const RadiusStats r = free_radii(s.simulation());
      const double half_d = 0.5 * c.particle.diameter, sp = c.particle.relative_spread;
      // Uniform +-s: std/mean = s/sqrt(3); normal: s (3-sigma cut: 0.986 s).
      const double want = dist == SizeDistribution::uniform ? sp / std::sqrt(3.0) : 0.986 * sp;
      const double cut = dist == SizeDistribution::uniform ? sp : 3 * sp;
      std::printf("%s %s: %zu free, mean d %.4f mm, std/mean %.4f (expected %.4f), range %.4f-%.4f mm\n",
                  slice ? "slice" : "drum", dist == SizeDistribution::uniform ? "uniform 10%" : "normal 5%", r.n,
                  2e3 * r.mean, r.rel_std, want, 2e3 * r.lo, 2e3 * r.hi);
      if (!slice) {
        EXPECT_GT(r.n, 1500u) << "the feeder inserted nothing";
      }
      EXPECT_NEAR(r.mean, half_d, 0.01 * half_d);
      EXPECT_NEAR(r.rel_std, want, 0.1 * want);  // 1500 samples: std of the estimate ~2 %
      EXPECT_GE(r.lo, half_d * (1 - cut) * (1 - 1e-12));
      EXPECT_LE(r.hi, half_d * (1 + cut) * (1 + 1e-12));
    }
  }
}

TEST(RetentionOptions, RoughWallStaysGluedAndCoRotates) {
  for (bool slice : {false, true}) {
    for (Lattice lat : {Lattice::square, Lattice::hexagonal}) {
      SceneConfig c = small(slice);
      c.rough_wall.enabled = true;
      c.rough_wall.lattice = lat;
      c.rough_wall.spacing = 1.3 * c.particle.diameter;
      c.initial_film.particles = 600;
      CentrecScene s(c);
      ASSERT_GT(s.glued_particles(), 100);
      s.advance(0.02);
      const auto& sim = s.simulation();
      const double rc = s.drum_radius() - 0.5 * c.rough_wall.sphere_diameter;
      double worst_r = 0, worst_v = 0, min_free_r = 1e9;
      for (std::size_t i = 0; i < sim.size(); ++i) {
        const Vec3 x = sim.positions()[i];
        if (sim.motions()[i] == Motion::free) {
          min_free_r = std::min(min_free_r, s.drum_radius() - std::hypot(x.x, x.y));
          continue;
        }
        worst_r = std::max(worst_r, std::fabs(std::hypot(x.x, x.y) - rc));
        worst_v = std::max(worst_v, norm(sim.velocities()[i] - cross(Vec3{0, 0, c.drum.omega}, x)));
      }
      std::printf("%s %s: %lld glued, radius error %.2e m, velocity error %.2e m/s, closest free centre %.3f d "
                  "from the wall\n",
                  slice ? "slice" : "drum", lat == Lattice::square ? "square" : "hexagonal",
                  static_cast<long long>(s.glued_particles()), worst_r, worst_v, min_free_r / c.particle.diameter);
      EXPECT_LT(worst_r, 1e-9);
      EXPECT_LT(worst_v, 1e-6);
      // Free spheres rest on the lattice, never on the wall: a 1.3 d square hole lets a
      // sphere sink to 0.894 d (centre), a hexagonal one to 1.06 d; overlaps give a little.
      EXPECT_GT(min_free_r, 0.85 * c.particle.diameter);
    }
  }
}

TEST(RetentionOptions, LipHoldsAFilmBelowItsHeight) {
  // A two-layer film with the outlet open loses particles within 0.1 s; a 3 d lip keeps
  // every one of them (nothing reaches its rim).
  double out[2];
  for (int k = 0; k < 2; ++k) {
    SceneConfig c = small(false);
    c.feeder.enabled = false;
    c.drum.lip_height = (k == 0 ? 0.0 : 3.0) * c.particle.diameter;
    c.initial_film.particles = 2200;
    CentrecScene s(c);
    s.advance(0.1);
    out[k] = s.mass_flow_log().back().out;
    std::printf("lip %.0f d: %.3g g out of %.3g g after 0.1 s\n", c.drum.lip_height / c.particle.diameter,
                out[k] * 1e3, (out[k] + s.holdup_mass()) * 1e3);
  }
  EXPECT_GT(out[0], 0.0);
  EXPECT_EQ(out[1], 0.0);
}

TEST(RetentionOptions, LipRefusedInASlice) {
  SceneConfig c = small(true);
  c.drum.lip_height = 2 * c.particle.diameter;
  c.initial_film.particles = 100;
  EXPECT_THROW(CentrecScene s(c), std::invalid_argument);
}

TEST(RetentionOptions, WallRollingModelReachesTheEngine) {
  for (bool slice : {false, true})
    for (WallRolling m : {WallRolling::relative, WallRolling::liggghts}) {
      SceneConfig c = small(slice);
      c.wall_rolling = m;
      // (Few particles shrink the engine's cell budget below 3 periodic cells: keep 600.)
      c.initial_film.particles = 600;
      CentrecScene s(c);
      EXPECT_EQ(s.simulation().config().wall_rolling, m);
    }
}
