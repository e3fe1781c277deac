// The engine's thread team (dem/thread_team.hpp): every part runs once, part p on thread p
// (the caller is thread 0), across many jobs and after the workers have gone to sleep.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dem/thread_team.hpp"

using centrec::dem::range_begin;
using centrec::dem::ThreadTeam;

TEST(ThreadTeam, EachPartOnceOnItsOwnThread) {
  ThreadTeam team(3);
  ASSERT_EQ(team.size(), 3);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> first(3);
  for (int job = 0; job < 2000; ++job) {
    std::vector<int> ran(3, 0);
    std::vector<std::thread::id> on(3);
    team.run(3, [&](int p) {
      ++ran[static_cast<std::size_t>(p)];
      on[static_cast<std::size_t>(p)] = std::this_thread::get_id();
    });
    for (int p = 0; p < 3; ++p) ASSERT_EQ(ran[static_cast<std::size_t>(p)], 1) << "job " << job << " part " << p;
    ASSERT_EQ(on[0], caller);
    ASSERT_NE(on[1], on[2]);
    ASSERT_NE(on[1], caller);
    if (job == 0) first = on;
    for (int p = 0; p < 3; ++p) ASSERT_EQ(on[static_cast<std::size_t>(p)], first[static_cast<std::size_t>(p)]);
  }
}

TEST(ThreadTeam, WakesSleepingWorkersAndSumsRanges) {
  ThreadTeam team(2);
  const long n = 100003;
  std::vector<double> x(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = static_cast<double>(i);
  for (int job = 0; job < 5; ++job) {
    // Longer than the spin: the worker is asleep on its condition variable when the job comes.
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    double part_sum[2] = {0.0, 0.0};
    team.run(2, [&](int p) {
      for (long i = range_begin(n, 2, p); i < range_begin(n, 2, p + 1); ++i) part_sum[p] += x[static_cast<std::size_t>(i)];
    });
    EXPECT_EQ(part_sum[0] + part_sum[1], static_cast<double>(n) * (n - 1) / 2.0);
  }
  EXPECT_EQ(range_begin(n, 2, 0), 0);
  EXPECT_EQ(range_begin(n, 2, 2), n);
}

TEST(ThreadTeam, FewerPartsThanThreadsAndRefusals) {
  ThreadTeam team(4);
  int calls = 0;
  team.run(1, [&](int p) { calls += 1 + p; });
  EXPECT_EQ(calls, 1);
  std::vector<int> ran(4, 0);
  team.run(2, [&](int p) { ++ran[static_cast<std::size_t>(p)]; });
  EXPECT_EQ(ran, (std::vector<int>{1, 1, 0, 0}));
  EXPECT_THROW(team.run(5, [](int) {}), std::invalid_argument);
  EXPECT_THROW(ThreadTeam(0), std::invalid_argument);
}
