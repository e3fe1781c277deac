// The override flags (apps/cli/case_overrides.cpp), declared once: the arguments a child
// process is given (override_args: `centrec sweep`'s points, `centrec run --replicas`) read
// back into the same overrides, every value to the bit, and config::effective_dem applies
// each of them, --wall-rolling-model included.
#include <gtest/gtest.h>

#include <string>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "config/case_checks.hpp"

using namespace centrec;

TEST(CaseOverrides, ChildArgumentsReadBackAsTheOverrides) {
  config::Overrides o;
  o.threads = 3;
  o.duration = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
  o.speed_rpm = 160.08;
  o.mass_flow = 1e-7;
  o.seed = 2147483647u;
  o.wall_rolling = dem::WallRolling::liggghts;
  const cli::Args args = cli::override_args(o);
  cli::CommandLine app("test");
  config::Overrides back;
  cli::add_override_flags(
      app, back,
      {cli::OverrideFlag::threads, cli::OverrideFlag::duration, cli::OverrideFlag::speed_rpm,
       cli::OverrideFlag::mass_flow, cli::OverrideFlag::seed, cli::OverrideFlag::wall_rolling_model});
  app.read(args);
  EXPECT_EQ(back.threads, o.threads);
  EXPECT_EQ(back.duration, o.duration);
  EXPECT_EQ(back.speed_rpm, o.speed_rpm);
  EXPECT_EQ(back.mass_flow, o.mass_flow);
  EXPECT_EQ(back.seed, o.seed);
  EXPECT_EQ(back.wall_rolling, o.wall_rolling);
  EXPECT_EQ(cli::override_flag_names().size() * 2, args.size());
  EXPECT_EQ(cli::flags_text(o),
            "--threads 3 --duration 0.30000000000000004 --speed-rpm 160.08 --mass-flow 1e-07 "
            "--seed 2147483647 --wall-rolling-model liggghts");
}

TEST(CaseOverrides, EffectiveDemAppliesTheWallRollingModel) {
  config::DemCase d;
  ASSERT_EQ(d.scene.wall_rolling, dem::WallRolling::relative);
  config::Overrides o;
  o.wall_rolling = dem::WallRolling::liggghts;
  EXPECT_EQ(config::effective_dem(d, nullptr, o).scene.wall_rolling, dem::WallRolling::liggghts);
  EXPECT_EQ(config::effective_dem(d, nullptr, {}).scene.wall_rolling, dem::WallRolling::relative);
}
