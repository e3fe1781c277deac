// Far-reaching neighbour lists (dem/first_half_step.hpp ListSlack, docs/dem_physics.md
// "Neighbour search"): a fast particle gets a half-skin that covers its flight over the
// next steps, lists its own pairs from a wider block of cells, and the list is rebuilt only
// when some pair's two displacements use up the two half-skins.
//  1. The list holds exactly the pairs the rule names (against a search of every pair),
//     each once, in a periodic cloud and an open one, on 1 and 2 threads.
//  2. Fast particles shot into a settling bed: the run is the same physics as one that
//     rebuilds at every step (round-off only), the same bits on 1 and 2 threads, and it
//     rebuilds far less often than at every skin/2 of the fastest particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "dem/neighbour_list.hpp"
#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

using Pair = std::pair<std::int32_t, std::int32_t>;

// The pairs of a cloud the list must hold: |x_i - x_j| < r_i + r_j + (h_i + h_j), with
// h = skin/2 unless far-reaching, every pair searched.
std::set<Pair> pairs_by_search(const std::vector<Vec3>& x, const std::vector<double>& r, const std::vector<double>& h,
                               const PeriodicZ& pz) {
  std::set<Pair> out;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      Vec3 d = x[i] - x[j];
      d.z = pz.image(d.z);
      const double cut = r[i] + r[j] + h[i] + h[j];
      if (norm2(d) < cut * cut) out.insert({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
    }
  return out;
}

void expect_list_is_the_rule(bool periodic, int threads) {
  // 3000 spheres of radius 0.45-0.55 in a 14 x 14 x 14 box (phi ~ 0.57); 2 % of them far
  // reaching, with half-skins up to 1.2.
  std::mt19937_64 rng(periodic ? 11 : 12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 3000;
  const double box = 14.0, skin = 0.2;
  PeriodicZ pz;
  pz.on = periodic;
  pz.lo = 0.0;
  pz.hi = box;
  std::vector<Vec3> x0(n);
  std::vector<double> r0(n), h0(n);
  std::vector<Motion> m0(n, Motion::free);
  for (int i = 0; i < n; ++i) {
    x0[i] = {box * u(rng), box * u(rng), box * u(rng)};
    r0[i] = 0.45 + 0.1 * u(rng);
    h0[i] = u(rng) < 0.02 ? 0.5 * skin + 1.1 * u(rng) : 0.5 * skin;
  }
  CellGrid grid;
  const std::vector<std::int32_t> order = sort_into_cells(grid, x0, 2 * 0.55 + skin, pz);
  std::vector<Vec3> x(n);
  std::vector<double> r(n), h(n);
  std::vector<Motion> motion(n);
  for (int k = 0; k < n; ++k) {
    x[k] = x0[order[k]];
    r[k] = r0[order[k]];
    h[k] = h0[order[k]];
    motion[k] = m0[order[k]];
  }
  ThreadTeam team(threads);
  ListBuildScratch scratch;
  NeighbourList list;
  build_neighbour_list(list, grid, x, r, motion, skin, h, pz, NeighbourList{}, team, scratch);
  std::set<Pair> listed;
  std::size_t entries = 0, reverse = 0;
  for (std::size_t i = 0; i < list.rows(); ++i)
    for (std::uint32_t e = list.start[i]; e < list.start[i + 1]; ++e) {
      const std::int32_t j = list.nbr[e];
      ++entries;
      if (j < static_cast<std::int32_t>(i)) ++reverse;
      listed.insert({std::min(static_cast<std::int32_t>(i), j), std::max(static_cast<std::int32_t>(i), j)});
    }
  const std::set<Pair> expected = pairs_by_search(x, r, h, pz);
  std::printf("far-reaching lists (%s, %d thread(s)): %zu entries (%zu naming a lower index), %zu pairs by search\n",
              periodic ? "periodic z" : "open", threads, entries, reverse, expected.size());
  EXPECT_EQ(entries, listed.size()) << "a pair listed twice";
  EXPECT_EQ(listed, expected);
  EXPECT_GT(reverse, 100u);  // the far-reaching rows did list partners of lower index
}

TEST(FarReachingLists, ListHoldsExactlyThePairsTheRuleNames) {
  for (bool periodic : {false, true})
    for (int threads : {1, 2}) expect_list_is_the_rule(periodic, threads);
}

struct Outcome {
  std::vector<Vec3> x, v;
  std::size_t rebuilds = 0, max_contacts = 0;
  double fastest = 0.0;
};

// A 20 x 20 x 3 lattice of columns (1200 particles) settling on a plane, and 24 particles
// shot at it from 2-5 d above at 1.4 m/s (a fed drum's falling particles), some of them
// crossing each other's paths; 500 steps of 1e-5 s, the shots arriving after ~1-3 ms.
Outcome shoot_into_bed(int threads, bool rebuild_each_step) {
  SimulationConfig cfg = quiet_config(1e-5, {0, 0, -9.81});
  cfg.threads = threads;
  cfg.max_impact_speed = 2.0;
  Simulation sim(cfg);
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.46, 0.5, 0.1});
  sim.add_wall(Wall::plane({0, 0, 0}, {0, 0, 1}, grain));
  const double d = 2.0 * kRadius, gap = 0.01 * kRadius, vgap = 1e-4 * kRadius;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) sim.add_particle({grain, kRadius, {i * (d + gap), j * (d + gap), kRadius + vgap + k * (d + vgap)}});
  const double top = kRadius + 3 * d, speed = 1.4;
  for (int s = 0; s < 24; ++s) {
    const double a = 0.5 + 0.8 * (s % 6), b = 2.0 + 3.0 * (s / 6);  // over the bed, in d
    const double angle = 0.4 * (s % 5) - 0.8;                         // from the vertical, rad
    const double turn = 1.3 * s;                                       // direction round the vertical
    const Vec3 dir{std::sin(angle) * std::cos(turn), std::sin(angle) * std::sin(turn), -std::cos(angle)};
    sim.add_particle({grain, kRadius, {(4 + 2.2 * a) * d, (2 + b) * d, top + (2 + 0.5 * (s % 7)) * d}, speed * dir});
  }
  std::size_t max_contacts = 0;
  double fastest = 0.0;
  for (int step = 0; step < 500; ++step) {
    sim.step(1);
    if (rebuild_each_step) sim.rebuild_lists();
    max_contacts = std::max(max_contacts, sim.neighbour_stats().pair_contacts);
    for (const Vec3& v : sim.velocities()) fastest = std::max(fastest, norm(v));
  }
  Outcome o;
  std::vector<std::size_t> by_id(sim.size());
  for (std::size_t i = 0; i < by_id.size(); ++i) by_id[i] = i;
  std::sort(by_id.begin(), by_id.end(), [&](std::size_t p, std::size_t q) { return sim.ids()[p] < sim.ids()[q]; });
  for (std::size_t i : by_id) {
    o.x.push_back(sim.positions()[i]);
    o.v.push_back(sim.velocities()[i]);
  }
  o.rebuilds = sim.neighbour_stats().rebuilds;
  o.max_contacts = max_contacts;
  o.fastest = fastest;
  return o;
}

TEST(FarReachingLists, FastParticlesIntoABedAreTheRunOfARebuildAtEveryStep) {
  const Outcome far1 = shoot_into_bed(1, false), far2 = shoot_into_bed(2, false);
  const Outcome every = shoot_into_bed(1, true);
  ASSERT_EQ(far1.x.size(), every.x.size());
  double dx = 0.0, dv = 0.0, vmax = 0.0;
  for (std::size_t k = 0; k < far1.x.size(); ++k) {
    dx = std::max(dx, norm(far1.x[k] - every.x[k]));
    dv = std::max(dv, norm(far1.v[k] - every.v[k]));
    vmax = std::max(vmax, norm(every.v[k]));
  }
  const bool same_bits = std::memcmp(far1.x.data(), far2.x.data(), far1.x.size() * sizeof(Vec3)) == 0 &&
                         std::memcmp(far1.v.data(), far2.v.data(), far1.v.size() * sizeof(Vec3)) == 0;
  // With one skin for all, the fastest particle would force a rebuild every skin/2 of its
  // flight: 0.12 mm at 1.4 m/s is 8.6 steps of 1e-5 s, ~58 rebuilds in 500 steps.
  const double skin = 0.2 * 2.0 * kRadius;
  const double one_skin_rebuilds = 500 * 1e-5 * 1.4 / (0.5 * skin);
  std::printf("fast particles into a bed: %zu rebuilds in 500 steps (one skin for all: ~%.0f; rebuilt every step: "
              "%zu); up to %zu pair contacts, fastest %.3g m/s; largest difference to the run rebuilt at every step "
              "|dx| %.3g m (%.3g d), |dv| %.3g m/s; 1 and 2 threads the same bits: %s\n",
              far1.rebuilds, one_skin_rebuilds, every.rebuilds, far1.max_contacts, far1.fastest, dx, dx / (2 * kRadius),
              dv, same_bits ? "yes" : "no");
  EXPECT_GT(far1.max_contacts, 700u);  // the bed is in contact
  EXPECT_GT(far1.fastest, 1.3);        // the shots flew
  EXPECT_LT(static_cast<double>(far1.rebuilds), 0.5 * one_skin_rebuilds);
  // Round-off only (the sums' order differs after each re-sort), as for the list edits.
  EXPECT_LT(dx, 1e-9 * 2 * kRadius);
  EXPECT_LT(dv, 1e-6 * std::max(vmax, 1e-3));
  EXPECT_TRUE(same_bits);
}

}  // namespace
