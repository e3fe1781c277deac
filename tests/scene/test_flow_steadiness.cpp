// Steady flow of a DEM run (dem/scene/mass_flow_window.hpp), on hand-made mass-flow logs:
// a drum is steady when its outlet matches the feed and its holdup holds within the
// tolerance; a controlled slice when its axial flow matches the target; anything filling,
// draining or still being corrected is not.
#include <gtest/gtest.h>

#include <cstdio>

#include "dem/scene/mass_flow_window.hpp"

using namespace centrec::dem::scene;

namespace {
// A log at 0.01 s intervals over 1 s: feed `in` kg/s, outlet `out` kg/s, holdup from h0
// following the balance; slice axial flow `axial`.
std::vector<MassFlowSample> log_of(double in, double out, double h0, double axial = 0.0) {
  std::vector<MassFlowSample> log;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    MassFlowSample s;
    s.time = t, s.fed = in * t, s.out = out * t, s.holdup = h0 + (in - out) * t, s.axial_flow = axial;
    log.push_back(s);
  }
  return log;
}
}  // namespace

TEST(FlowSteadiness, FedDrum) {
  SceneConfig drum;
  drum.feeder.mass_flow = 0.01;
  const auto ok = flow_steadiness(log_of(0.01, 0.0098, 0.05), drum, 0.5, 0.05);
  std::printf("%s\n", ok.describe().c_str());
  EXPECT_TRUE(ok.steady);
  EXPECT_NEAR(ok.flow_error, -0.02, 1e-9);
  EXPECT_NEAR(ok.measured, 0.0098, 1e-12);
  // The quickstart at D/d 25 as a user saw it: outlet 8.08 against a feed of 8.92 g/s.
  const auto filling = flow_steadiness(log_of(8.92e-3, 8.08e-3, 0.05), drum, 0.5, 0.05);
  std::printf("%s\n", filling.describe().c_str());
  EXPECT_FALSE(filling.steady);
  EXPECT_NEAR(filling.flow_error, 8.08 / 8.92 - 1.0, 1e-9);
  // Outlet = feed but the holdup is being emptied elsewhere (lost particles): drift 10 %.
  auto leaking = log_of(0.01, 0.01, 0.05);
  for (auto& s : leaking) s.holdup = 0.05 * (1.0 - 0.2 * s.time);
  EXPECT_FALSE(flow_steadiness(leaking, drum, 0.5, 0.05).steady);
  EXPECT_TRUE(flow_steadiness(leaking, drum, 0.5, 0.15).steady);
  // Too short a log says nothing.
  EXPECT_FALSE(flow_steadiness({MassFlowSample{}}, drum, 0.5, 0.05).steady);
}

TEST(FlowSteadiness, AFedDrumsFillingWaveCrossingTheFeedIsNotSteady) {
  // A fed drum fills in a wave: its outflow rises through the feed on its way to an
  // overshoot. Over one window astride the crossing (here the outlet ramps 5 -> 15 g/s about
  // a 10 g/s feed) the mean outflow is the feed and the holdup ends where it began, which a
  // one-window test calls steady (the D/d 100 drum's spin-up ended so at a wave's crest); the
  // window before (outlet 5 g/s) is not, so the drum is not.
  SceneConfig drum;
  drum.feeder.mass_flow = 0.01;
  std::vector<MassFlowSample> log;
  double out = 0.0, holdup = 0.05;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k, rate = t < 0.5 ? 0.005 : 0.005 + 0.02 * (t - 0.5);
    if (k > 0) {
      const double prev = log.back().time < 0.5 ? 0.005 : 0.005 + 0.02 * (log.back().time - 0.5);
      out += 0.5 * (rate + prev) * 0.01;
      holdup += 0.01 * 0.01 - 0.5 * (rate + prev) * 0.01;
    }
    MassFlowSample s;
    s.time = t, s.fed = 0.01 * t, s.out = out, s.holdup = holdup;
    log.push_back(s);
  }
  const auto crossing = flow_steadiness(log, drum, 0.5, 0.05);
  std::printf("%s\n", crossing.describe().c_str());
  EXPECT_NEAR(crossing.flow_error, 0.0, 1e-9);     // the last window alone: the feed's
  EXPECT_NEAR(crossing.holdup_drift, 0.0, 1e-9);   // and a flat holdup
  EXPECT_NEAR(crossing.previous_flow_error, -0.5, 1e-9);
  EXPECT_FALSE(crossing.steady);
  // A steady drum whose outflow scatters +-8 % from one tenth of a second to the next is steady.
  std::vector<MassFlowSample> noisy;
  out = 0.0;
  for (int k = 0; k <= 100; ++k) {
    MassFlowSample s;
    s.time = 0.01 * k;
    if (k > 0) out += 0.01 * 0.01 * ((k / 10) % 2 ? 1.08 : 0.92);
    s.fed = 0.01 * s.time, s.out = out, s.holdup = 0.05 + s.fed - s.out;
    noisy.push_back(s);
  }
  const auto steady = flow_steadiness(noisy, drum, 0.5, 0.05);
  std::printf("%s\n", steady.describe().c_str());
  EXPECT_TRUE(steady.steady);
  // A log shorter than two windows cannot show it.
  noisy.resize(60);
  EXPECT_FALSE(flow_steadiness(noisy, drum, 0.5, 0.05).steady);
}

TEST(FlowSteadiness, ControlledAndFreeSlice) {
  SceneConfig slice;
  slice.slice.enabled = true;
  slice.slice.target_mass_flow = 0.02;
  const auto ok = flow_steadiness(log_of(0, 0, 0.01, 0.0195), slice, 0.5, 0.05);
  std::printf("%s\n", ok.describe().c_str());
  EXPECT_TRUE(ok.steady);
  EXPECT_NEAR(ok.flow_error, -0.025, 1e-9);
  EXPECT_FALSE(flow_steadiness(log_of(0, 0, 0.01, 0.015), slice, 0.5, 0.05).steady);
  // Without a target the window's halves are compared: a decaying flow is not steady.
  slice.slice.target_mass_flow = 0.0;
  auto decaying = log_of(0, 0, 0.01);
  for (auto& s : decaying) s.axial_flow = 0.02 * (1.0 - 0.5 * s.time);
  const auto free = flow_steadiness(decaying, slice, 0.5, 0.05);
  std::printf("%s\n", free.describe().c_str());
  EXPECT_FALSE(free.steady);
  EXPECT_TRUE(flow_steadiness(log_of(0, 0, 0.01, 0.02), slice, 0.5, 0.05).steady);
}
