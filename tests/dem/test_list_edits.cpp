// Particles inserted and removed without a rebuild (dem/simulation_list_edits.cpp): the
// run is the same physics as one that rebuilds the lists after every insertion and removal
// (equal to round-off: only the order of the sums differs), the same bits on 1 and 2
// threads, and a particle inserted right next to others is in contact with them from its
// first step (it is listed with its old neighbours, the "reverse" entries).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

struct Outcome {
  std::vector<std::int64_t> id;
  std::vector<Vec3> x, v;
  std::size_t rebuilds = 0, edits = 0, max_contacts = 0;
};

// A 20 x 20 x 3 lattice of columns (1200 particles, above the engine's threading threshold)
// settling onto a plane under gravity (each sphere 1e-4 radii above the one below); every 10 steps a particle is dropped onto its
// top (0.5 % of a radius above a bed particle, moving down at 0.05 m/s, so it hits within a
// few steps), and every 15 steps a bed particle and the oldest dropped one are taken out.
// `rebuild_each_edit` makes the lists again right after every edit (the reference path).
Outcome drop_and_remove(int threads, bool rebuild_each_edit) {
  SimulationConfig cfg = quiet_config(2e-6, {0, 0, -9.81});
  cfg.threads = threads;
  Simulation sim(cfg);
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.46, 0.5, 0.1});
  sim.add_wall(Wall::plane({0, 0, 0}, {0, 0, 1}, grain));
  const double d = 2.0 * kRadius, gap = 0.01 * kRadius, vgap = 1e-4 * kRadius;  // side by side, one on another
  std::vector<std::int64_t> bed, dropped;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
        bed.push_back(sim.add_particle({grain, kRadius, {i * (d + gap), j * (d + gap), kRadius + vgap + k * (d + vgap)}}));
  const double top = kRadius + vgap + 2 * (d + vgap);
  std::size_t max_contacts = 0;
  for (int step = 0; step < 600; ++step) {
    bool edited = false;
    if (step % 10 == 5) {  // each drop on a site of its own (sites (a, b), b in 1, 7, 13, 19)
      const int k = step / 10, a = k % 19, b = (k / 19) * 6 + 1;
      dropped.push_back(sim.add_particle({grain, kRadius, {a * (d + gap), b * (d + gap), top + d + 0.005 * kRadius},
                                          {0, 0, -0.05}}));
      edited = true;
    }
    if (step % 15 == 7) {
      sim.remove_particles({bed[static_cast<std::size_t>((13 * step) % 400)]});
      if (dropped.size() > 8) {
        sim.remove_particles({dropped.front()});
        dropped.erase(dropped.begin());
      }
      edited = true;
    }
    if (edited && rebuild_each_edit) sim.rebuild_lists();
    sim.step(1);
    max_contacts = std::max(max_contacts, sim.neighbour_stats().pair_contacts);
  }
  Outcome o;
  std::vector<std::size_t> by_id(sim.size());
  for (std::size_t i = 0; i < by_id.size(); ++i) by_id[i] = i;
  std::sort(by_id.begin(), by_id.end(), [&](std::size_t a, std::size_t b) { return sim.ids()[a] < sim.ids()[b]; });
  for (std::size_t i : by_id) {
    o.id.push_back(sim.ids()[i]);
    o.x.push_back(sim.positions()[i]);
    o.v.push_back(sim.velocities()[i]);
  }
  o.rebuilds = sim.neighbour_stats().rebuilds;
  o.edits = sim.neighbour_stats().list_edits;
  o.max_contacts = max_contacts;
  return o;
}

}  // namespace

TEST(ListEdits, SameRunAsARebuildAtEveryEditAndTheSameBitsOnTwoThreads) {
  const Outcome local1 = drop_and_remove(1, false), local2 = drop_and_remove(2, false);
  const Outcome rebuilt = drop_and_remove(1, true);
  ASSERT_EQ(local1.id, rebuilt.id);
  ASSERT_EQ(local1.id, local2.id);
  double dx = 0.0, dv = 0.0, vmax = 0.0;
  for (std::size_t k = 0; k < local1.x.size(); ++k) {
    dx = std::max(dx, norm(local1.x[k] - rebuilt.x[k]));
    dv = std::max(dv, norm(local1.v[k] - rebuilt.v[k]));
    vmax = std::max(vmax, norm(rebuilt.v[k]));
  }
  const bool same_bits = std::memcmp(local1.x.data(), local2.x.data(), local1.x.size() * sizeof(Vec3)) == 0 &&
                         std::memcmp(local1.v.data(), local2.v.data(), local1.v.size() * sizeof(Vec3)) == 0;
  std::printf("list edits: %zu edits and %zu rebuilds without rebuilding at an edit, %zu rebuilds with; %zu particles, "
              "up to %zu pair contacts; largest difference to the rebuilt run |dx| %.3g m (%.3g d), |dv| %.3g m/s "
              "(fastest particle %.3g m/s); 1 and 2 threads the same bits: %s\n",
              local1.edits, local1.rebuilds, rebuilt.rebuilds, local1.x.size(), local1.max_contacts, dx, dx / (2 * kRadius),
              dv, vmax, same_bits ? "yes" : "no");
  EXPECT_GT(local1.edits, 80u);          // every insertion and removal worked in locally
  EXPECT_LT(local1.rebuilds, 10u);       // ... and none of them rebuilt
  EXPECT_GT(rebuilt.rebuilds, 80u);
  EXPECT_GT(local1.max_contacts, 700u);  // the columns are in contact (the runs did work)
  // Round-off only: 600 steps of a contact network stay within 1e-9 d and 1e-6 of the speeds.
  EXPECT_LT(dx, 1e-9 * 2 * kRadius);
  EXPECT_LT(dv, 1e-6 * std::max(vmax, 1e-3));
  EXPECT_TRUE(same_bits);
}

TEST(ListEdits, ParticleInsertedNextToAnotherTouchesItAtOnce) {
  // Two equal particles, no gravity: A at rest; B inserted 1 % of a radius above it, moving
  // down at 0.1 m/s. With a valid list B must be listed with A (a reverse entry in B's row,
  // A's share parked): a head-on impact with restitution e leaves B at -(1 - e)/2 x 0.1 and
  // A at -(1 + e)/2 x 0.1 m/s (momentum conserved exactly by the pair's third law).
  const double e = 0.9, v0 = -0.1;
  Simulation sim(quiet_config(1e-6));
  const MaterialId grain = use_paper_material(sim, PairInteraction{e, 0.5, 0.0});
  const std::int64_t a = sim.add_particle({grain, kRadius, {0, 0, 0}});
  sim.step(10);  // list built and valid
  const std::int64_t b = sim.add_particle({grain, kRadius, {0, 0, 2.01 * kRadius}, {0, 0, v0}});
  sim.step(1500);  // contact at ~60 us, over by ~0.7 ms (Hertz at 0.1 m/s)
  const double va = sim.velocities()[static_cast<std::size_t>(sim.index_of(a))].z;
  const double vb = sim.velocities()[static_cast<std::size_t>(sim.index_of(b))].z;
  std::printf("inserted particle: %zu list edits, %zu rebuilds; after the impact B %.5g m/s (expected %.5g), A %.5g "
              "m/s (expected %.5g), momentum %.3g of the start's\n",
              sim.neighbour_stats().list_edits, sim.neighbour_stats().rebuilds, vb, 0.5 * (1 - e) * v0, va,
              0.5 * (1 + e) * v0, (va + vb) / v0);
  EXPECT_GE(sim.neighbour_stats().list_edits, 1u);
  EXPECT_EQ(sim.neighbour_stats().pair_contacts, 0u);  // the impact is over
  // The Hertz-Mindlin damping is set for e (make_pair_constants); 2 % of v0 covers its
  // discretisation at 1e-6 s.
  EXPECT_NEAR(vb, 0.5 * (1 - e) * v0, 0.02 * std::fabs(v0));
  EXPECT_NEAR(va, 0.5 * (1 + e) * v0, 0.02 * std::fabs(v0));
  EXPECT_NEAR((va + vb) / v0, 1.0, 1e-12);
}
