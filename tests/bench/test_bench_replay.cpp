// The benchmark's equal-window protocol (--replay-particle-steps): how many windows each
// size replays, and that a replayed window is the same run as the first one, so every
// timed phase of a small film measures the same work as the large film's phases.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_options.hpp"
#include "bench/centrec_run.hpp"
#include "bench/film_initial_state.hpp"

namespace centrec::bench {
namespace {

BenchOptions parse(std::vector<std::string> args) {
  std::vector<char*> argv{const_cast<char*>("bench")};
  for (auto& a : args) argv.push_back(a.data());
  return parse_bench_options(static_cast<int>(argv.size()), argv.data());
}

TEST(BenchReplay, WindowsPerSizeGiveEqualWork) {
  const BenchOptions o = parse({"--steps", "500", "--repeats", "3", "--replay-particle-steps", "3e8"});
  // window = N x 500 x 3 particle-steps
  EXPECT_EQ(replays_for(o, 10000, 0), 20);
  EXPECT_EQ(replays_for(o, 50000, 1), 4);
  EXPECT_EQ(replays_for(o, 200000, 2), 1);
  EXPECT_EQ(replays_for(o, 400000, 2), 1);  // at least one window
  const BenchOptions plain = parse({"--steps", "500"});
  EXPECT_EQ(replays_for(plain, 10000, 0), 1);
  EXPECT_THROW(parse({"--replay-particle-steps", "1e8", "--phase-particle-steps", "1e8"}), std::invalid_argument);
}

TEST(BenchReplay, ReplayedWindowIsTheSameRun) {
  const FilmCase c;
  const FilmState s = make_film_lattice(c, 4000);
  CentrecRunSettings r;
  r.settle_steps = 300;
  r.timed_steps = 20;
  r.repeats = 2;
  r.replays = 1;
  const EngineResult once = run_centrec(c, s, r);
  r.replays = 3;
  const EngineResult thrice = run_centrec(c, s, r);
  ASSERT_TRUE(once.ok) << once.note;
  ASSERT_TRUE(thrice.ok) << thrice.note;
  EXPECT_EQ(once.seconds.size(), 2u);
  EXPECT_EQ(thrice.seconds.size(), 6u);
  std::printf("film of %ld particles, window 2 x 20 steps: final KE %.17g J once, %.17g J after 3 replays; "
              "rebuilds per phase %.3f / %.3f\n",
              once.particles, once.final.kinetic_energy, thrice.final.kinetic_energy, once.rebuilds_per_phase,
              thrice.rebuilds_per_phase);
  // Bit for bit: the replays end where the single window ended.
  EXPECT_EQ(once.final.kinetic_energy, thrice.final.kinetic_energy);
  EXPECT_EQ(once.final.rotational_energy, thrice.final.rotational_energy);
  EXPECT_EQ(once.final.mean_vz, thrice.final.mean_vz);
  EXPECT_EQ(once.final.pair_contacts, thrice.final.pair_contacts);
  EXPECT_EQ(once.rebuilds_per_phase, thrice.rebuilds_per_phase);
  EXPECT_GT(once.final.pair_contacts, 0.0);  // the window is a real, contacting film
}

}  // namespace
}  // namespace centrec::bench
