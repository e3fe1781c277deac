// (h) 1-thread and 2-thread runs agree BITWISE (and 3-thread ones, whose row ranges split
// the film elsewhere): every pair is evaluated in a canonical operand order, the shares on
// each partner are summed in row order whether added directly or parked by a range
// boundary (dem/partner_routing.hpp), and wall-force sums are reduced over fixed blocks in
// a fixed order (see dem/simulation.hpp). Also: the same
// steps taken in one step() call or in many agree bitwise (inside a call the force pass
// fuses the next step's first half, which a call boundary does in a sweep of its own).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>

#include "film_scene.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

struct Snapshot {
  std::map<std::int64_t, std::array<Vec3, 3>> state;  // by id: x, v, w
  std::vector<Vec3> wall_forces;
  std::size_t contacts;
};

// 600 steps in step() calls of `chunk` steps.
Snapshot run(int threads, long chunk = 600) {
  FilmScene scene;
  scene.threads = threads;
  scene.length = 6e-3;  // a short drum: 2000 particles make a film of about three layers
  Simulation sim(film_config(scene));
  build_film(sim, scene, 2000);
  for (long done = 0; done < 600; done += chunk) sim.step(std::min(chunk, 600 - done));
  Snapshot s;
  for (std::size_t i = 0; i < sim.size(); ++i)
    s.state[sim.ids()[i]] = {sim.positions()[i], sim.velocities()[i], sim.angular_velocities()[i]};
  for (std::size_t w = 0; w < sim.wall_count(); ++w) s.wall_forces.push_back(sim.wall_force(static_cast<int>(w)));
  s.contacts = sim.neighbour_stats().pair_contacts;
  return s;
}

// Particles whose state differs in any bit between the two runs.
std::size_t differing_particles(const Snapshot& a, const Snapshot& b) {
  EXPECT_EQ(a.state.size(), b.state.size());
  std::size_t differing = 0;
  for (const auto& [id, sa] : a.state) {
    const auto& sb = b.state.at(id);
    if (std::memcmp(sa.data(), sb.data(), sizeof sa) != 0) ++differing;
  }
  return differing;
}

bool walls_equal(const Snapshot& a, const Snapshot& b) {
  return a.wall_forces.size() == b.wall_forces.size() &&
         std::memcmp(a.wall_forces.data(), b.wall_forces.data(), a.wall_forces.size() * sizeof(Vec3)) == 0;
}

}  // namespace

TEST(ThreadDeterminism, OneAndTwoThreadsAgreeBitwise) {
  const Snapshot a = run(1), b = run(2), c = run(3);
  const std::size_t differing = differing_particles(a, b), differing3 = differing_particles(a, c);
  std::printf("(h) film of %zu particles, 600 steps, %zu pair contacts: %zu particles differ bitwise between 1 and "
              "2 threads, %zu between 1 and 3 (tolerance 0); wall forces identical: %s, %s\n",
              a.state.size(), a.contacts, differing, differing3, walls_equal(a, b) ? "yes" : "no",
              walls_equal(a, c) ? "yes" : "no");
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(differing3, 0u);
  EXPECT_TRUE(walls_equal(a, b));
  EXPECT_TRUE(walls_equal(a, c));
  EXPECT_GT(a.contacts, 500u);  // the film is dense: the comparison exercises contacts
}

TEST(ThreadDeterminism, OneCallAndManyCallsAgreeBitwise) {
  const Snapshot a = run(1), b = run(1, 7), c = run(1, 1);
  const std::size_t d7 = differing_particles(a, b), d1 = differing_particles(a, c);
  std::printf("600 steps as one step() call vs calls of 7 and of 1 step (1 thread): %zu and %zu of %zu particles "
              "differ bitwise (tolerance 0); wall forces identical: %s, %s\n",
              d7, d1, a.state.size(), walls_equal(a, b) ? "yes" : "no", walls_equal(a, c) ? "yes" : "no");
  EXPECT_EQ(d7, 0u);
  EXPECT_EQ(d1, 0u);
  EXPECT_TRUE(walls_equal(a, b));
  EXPECT_TRUE(walls_equal(a, c));
}
