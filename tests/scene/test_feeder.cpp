// The feeder inserts at the target mass flow (within 2 %), never overlapping, with the
// wall's tangential speed and no axial velocity (docs/centrec_scene.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dem/scene/centrec_scene.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

namespace {
SceneConfig small_drum() {
  SceneConfig c;
  c.drum.diameter = 0.04;
  c.drum.length = 0.057;
  c.drum.omega = 277.26 * 2 * M_PI / 60;
  c.feeder.mass_flow = 11.9e-3;
  c.dt = 1e-5;
  c.threads = 1;
  return c;
}
}  // namespace

TEST(Feeder, RateWithinTwoPercentOfTarget) {
  for (auto dist : {SizeDistribution::mono, SizeDistribution::uniform}) {
    SceneConfig c = small_drum();
    c.particle.distribution = dist;
    c.particle.relative_spread = dist == SizeDistribution::mono ? 0.0 : 0.1;
    CentrecScene s(c);
    const double T = 0.1;
    s.advance(T);
    const double rate = s.feeder_stats().inserted_mass / T;
    std::printf("feeder (%s): %.4f g/s achieved vs %.4f g/s target (%.2f %%), %lld particles, %lld deferred\n",
                dist == SizeDistribution::mono ? "mono" : "uniform 10%", rate * 1e3, c.feeder.mass_flow * 1e3,
                100.0 * (rate / c.feeder.mass_flow - 1.0), static_cast<long long>(s.feeder_stats().inserted),
                static_cast<long long>(s.feeder_stats().deferred));
    EXPECT_NEAR(rate / c.feeder.mass_flow, 1.0, 0.02);
  }
}

// A region too small for its flow defers insertions; after one turn the run is told why,
// with the rate delivered and the keys to change. The same drum with the default region
// keeps up (no message).
TEST(Feeder, ShortfallAfterOneTurnNamesTheRegionKeys) {
  for (bool small : {false, true}) {
    SceneConfig c = small_drum();
    if (small) {
      c.feeder.radial_height = 1.05 * c.particle.diameter;  // centres within 0.05 d radially
      c.feeder.axial_length = 1.05 * c.particle.diameter;
    }
    CentrecScene s(c);
    const double turn = 2.0 * M_PI / c.drum.omega;
    s.advance(turn);
    const std::string why = feeder_shortfall(c, s.feeder_stats(), turn);
    const double rate = s.feeder_stats().inserted_mass / turn;
    std::printf("region %s: %.3f of %.3f g/s delivered over one turn, %lld deferred: \"%s\"\n",
                small ? "1.05 d x 1.05 d" : "default", rate * 1e3, c.feeder.mass_flow * 1e3,
                static_cast<long long>(s.feeder_stats().deferred), why.c_str());
    if (small) {
      EXPECT_LT(rate, 0.9 * c.feeder.mass_flow);
      EXPECT_NE(why.find("radial_height_d"), std::string::npos);
      EXPECT_NE(why.find("axial_length_d"), std::string::npos);
    } else {
      EXPECT_TRUE(why.empty()) << why;
    }
  }
}

TEST(Feeder, InsertsWithWallSpeedAndNoOverlap) {
  SceneConfig c = small_drum();
  CentrecScene s(c);
  // One batch: particles are fresh, check their state before they collide.
  auto& sim = s.simulation();
  s.advance(c.feeder.interval);
  ASSERT_GT(sim.size(), 2u);
  const double R = 0.5 * c.drum.diameter, speed = c.drum.omega * R;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const Vec3 v = sim.velocities()[i];
    EXPECT_NEAR(std::hypot(v.x, v.y), speed, 0.02 * speed);
    EXPECT_NEAR(v.z, 0.0, 0.05 * speed);  // gravity acts for one batch only
    for (std::size_t j = i + 1; j < sim.size(); ++j) {
      const double dist = norm(sim.positions()[i] - sim.positions()[j]);
      EXPECT_GE(dist, sim.radii()[i] + sim.radii()[j] - 1e-9);
    }
  }
}
