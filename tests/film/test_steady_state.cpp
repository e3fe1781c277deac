// Steady-state detection on synthetic inlet/outlet mass-flow series.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dem/film/steady_state.hpp"

using namespace centrec::film;

TEST(SteadyState, FindsTheAnalyticTimeOfAnExponentialFill) {
  // Outlet rate mdot (1 - exp(-t/tau)); its mean over a window W ending at T falls short
  // of mdot by (tau/W) e^{-T/tau} (e^{W/tau} - 1): steady (2 %) from
  // T = tau ln((e^{W/tau} - 1) tau / (0.02 W)).
  const double mdot = 35.7e-3, tau = 1.0, W = 1.0, dt = 0.01;
  std::vector<double> t, in, out;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(i * dt);
    in.push_back(mdot);
    // Sample i is the mean over (t[i-1], t[i]]: the exact integral of the exponential.
    const double a = (i - 1) * dt, b = i * dt;
    out.push_back(i ? mdot * (1.0 - tau * (std::exp(-a / tau) - std::exp(-b / tau)) / dt) : 0.0);
  }
  SteadyStateCriterion c;
  c.window = W;
  c.tolerance = 0.02;
  const SteadyStateResult r = find_steady_state(t.data(), in.data(), out.data(), t.size(), c);
  const double expect = tau * std::log((std::exp(W / tau) - 1.0) * tau / (0.02 * W));
  std::printf("exponential fill: steady at %.3f s (analytic %.3f s), outlet %.2f g/s vs inlet %.2f g/s\n", r.time,
              expect, r.outlet_mean * 1e3, r.inlet_mean * 1e3);
  ASSERT_TRUE(r.steady);
  EXPECT_GE(r.time, expect - 1e-9);
  EXPECT_LT(r.time, expect + dt + 1e-9);
  EXPECT_NEAR(r.outlet_mean / r.inlet_mean, 0.98, 0.002);
}

TEST(SteadyState, NoisyIrregularSeriesAndNeverSteady) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> jitter(0.005, 0.02);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<double> t{0.0}, in{0.0}, out{0.0}, half{0.0};
  while (t.back() < 20.0) {
    t.push_back(t.back() + jitter(rng));
    in.push_back(1.0 + noise(rng));
    out.push_back(t.back() < 5.0 ? 0.3 : 1.0 + noise(rng));  // outlet jumps to the inlet rate at 5 s
    half.push_back(0.5);
  }
  SteadyStateCriterion c;
  c.window = turns_to_seconds(4.0, 2 * M_PI);  // 4 turns at 1 turn/s
  EXPECT_NEAR(c.window, 4.0, 1e-12);
  c.tolerance = 0.05;
  const SteadyStateResult r = find_steady_state(t.data(), in.data(), out.data(), t.size(), c);
  std::printf("noisy series (outlet reaches the inlet rate at 5 s, 4 s window, 5 %%): steady at %.2f s\n", r.time);
  ASSERT_TRUE(r.steady);
  EXPECT_GT(r.time, 5.0 + 0.9 * c.window - 0.5);
  EXPECT_LT(r.time, 5.0 + c.window + 0.5);
  const SteadyStateResult never = find_steady_state(t.data(), in.data(), half.data(), t.size(), c);
  EXPECT_FALSE(never.steady);
  EXPECT_TRUE(std::isnan(never.time));
  EXPECT_NEAR(never.outlet_mean, 0.5, 1e-9);
  const double bad_t[] = {0.0, 0.0};
  EXPECT_THROW(find_steady_state(bad_t, in.data(), out.data(), 2, c), std::invalid_argument);
}
