// (a) Head-on impacts, particle-particle and particle-wall: restitution within 1 % of the
// input e for e in {0.2, 0.46, 0.9}; with e = 1 the contact lasts the Hertz time
// t_c = 2.868 (m*^2/(R* E*^2 v))^(1/5) within 2 %, at two speeds.
#include <gtest/gtest.h>

#include <cstdio>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

struct ImpactResult {
  double restitution;
  double duration;  // s, steps with a contact x dt
};

// Two spheres approaching along x at relative speed v, or one sphere hitting the plane x = 0.
ImpactResult head_on(double e, double v, bool wall) {
  const double tc = paper_contact_time(v, wall);
  Simulation sim(quiet_config(tc / 1000.0));
  const MaterialId grain = use_paper_material(sim, PairInteraction{e, 0.5, 0.0});
  const double gap = 0.05 * kRadius;
  if (wall) {
    sim.add_wall(Wall::plane({0, 0, 0}, {1, 0, 0}, grain));
    sim.add_particle({grain, kRadius, {kRadius + gap, 0, 0}, {-v, 0, 0}, {}});
  } else {
    sim.add_particle({grain, kRadius, {-kRadius - 0.5 * gap, 0, 0}, {0.5 * v, 0, 0}, {}});
    sim.add_particle({grain, kRadius, {kRadius + 0.5 * gap, 0, 0}, {-0.5 * v, 0, 0}, {}});
  }
  long in_contact = 0;
  bool touched = false;
  for (int s = 0; s < 20000; ++s) {
    sim.step(1);
    const auto st = sim.neighbour_stats();
    const bool c = st.pair_contacts + st.wall_contacts > 0;
    in_contact += c;
    touched = touched || c;
    if (touched && !c) break;
  }
  const auto& vel = sim.velocities();
  double v_after;
  if (wall) {
    v_after = vel[0].x;
  } else {
    const std::ptrdiff_t a = sim.index_of(0), b = sim.index_of(1);
    v_after = vel[static_cast<std::size_t>(b)].x - vel[static_cast<std::size_t>(a)].x;
  }
  return {v_after / v, static_cast<double>(in_contact) * sim.dt()};
}

}  // namespace

TEST(HeadOnImpact, RestitutionMatchesInput) {
  for (bool wall : {false, true}) {
    for (double e : {0.2, 0.46, 0.9}) {
      const ImpactResult r = head_on(e, 1.0, wall);
      std::printf("(a) %s impact at 1 m/s, e = %.2f: measured e = %.5f (error %+.3f %%, tolerance 1 %%)\n",
                  wall ? "particle-wall" : "particle-particle", e, r.restitution, 100.0 * (r.restitution / e - 1.0));
      EXPECT_NEAR(r.restitution / e, 1.0, 0.01) << (wall ? "wall" : "pair") << " e=" << e;
    }
  }
}

TEST(HeadOnImpact, ElasticContactLastsHertzTime) {
  for (bool wall : {false, true}) {
    for (double v : {0.2, 2.0}) {
      const ImpactResult r = head_on(1.0, v, wall);
      const double tc = paper_contact_time(v, wall);
      std::printf("(a) %s e = 1 at %.1f m/s: contact %.4e s, Hertz %.4e s (error %+.3f %%, tolerance 2 %%), "
                  "rebound e = %.6f\n",
                  wall ? "particle-wall" : "particle-particle", v, r.duration, tc, 100.0 * (r.duration / tc - 1.0),
                  r.restitution);
      EXPECT_NEAR(r.duration / tc, 1.0, 0.02);
      EXPECT_NEAR(r.restitution, 1.0, 1e-3);
    }
  }
}
