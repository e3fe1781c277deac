// The override flags (apps/cli/case_overrides.cpp), declared once: the arguments a child
// process is given (override_args: `centrec sweep`'s points, `centrec run --replicas`) read
// back into the same overrides, every value to the bit; config::with_overrides writes any
// case key into the case and reads it again, so the key's own reader checks it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "config/case_checks.hpp"
#include "config/case_file.hpp"

using namespace centrec;

TEST(CaseOverrides, ChildArgumentsReadBackAsTheOverrides) {
  config::Overrides o;
  o.keys["dem.run.threads"] = "3";
  o.keys["dem.seed"] = "2147483647";
  o.keys["thermal.T_in"] = "900.5";
  o.keys["thermal.flux.q_film"] = "0.30000000000000004";
  o.speed_rpm = 160.08;
  o.mass_flow = 1e-7;
  o.keys["dem.run.duration"] = "0.5";  // `dem`'s own flag; `run` takes it by --set
  const cli::Args args = cli::override_args(o, "run");
  cli::CommandLine app("test");
  config::Overrides back;
  cli::add_override_flags(app, back, "run");
  app.read(args);
  EXPECT_EQ(back.keys, o.keys);
  EXPECT_EQ(back.speed_rpm, o.speed_rpm);
  EXPECT_EQ(back.mass_flow, o.mass_flow);
  // A key with a flag of its own that the command takes goes by that flag, any other by --set.
  std::string text;
  for (const std::string& a : args) text += (text.empty() ? "" : " ") + a;
  EXPECT_EQ(text,
            "--threads 3 --speed-rpm 160.08 --mass-flow 1e-07 --seed 2147483647 --set dem.run.duration=0.5 "
            "--set thermal.T_in=900.5 --set thermal.flux.q_film=0.30000000000000004");
  // Messages name the flags as the command takes them: `dem` has --duration but no --seed.
  EXPECT_EQ(cli::flags_text(o, "run"), text);
  EXPECT_EQ(cli::flags_text(o, "dem"),
            "--threads 3 --duration 0.5 --speed-rpm 160.08 --mass-flow 1e-07 --set dem.seed=2147483647 "
            "--set thermal.T_in=900.5 --set thermal.flux.q_film=0.30000000000000004");
  for (const char* name : {"--threads", "--speed-rpm", "--mass-flow", "--seed", "--set"})
    EXPECT_NE(std::find(cli::override_flag_names().begin(), cli::override_flag_names().end(), name),
              cli::override_flag_names().end())
        << name;
}

TEST(CaseOverrides, EachCommandTakesItsOwnFlags) {
  // `centrec dem` runs no thermal model and has no operating point of its own; `thermal` runs no DEM.
  EXPECT_EQ(cli::override_keys("dem"),
            (std::vector<std::string>{"dem.run.threads", "dem.run.duration", "dem.contacts.wall_rolling_model"}));
  EXPECT_EQ(cli::override_keys("run"), (std::vector<std::string>{"dem.run.threads", "dem.seed"}));
  EXPECT_TRUE(cli::override_keys("thermal").empty());
  cli::CommandLine thermal("thermal");
  config::Overrides o;
  cli::add_override_flags(thermal, o, "thermal");
  EXPECT_THROW(thermal.read({"--threads", "2"}), cli::UsageError);
  EXPECT_THROW(thermal.read({"--set", "thermal.T_in"}), cli::UsageError);  // not KEY=VALUE
  thermal.read({"--set", "thermal.T_in=900", "--set", "thermal.flux.q_film=3e5"});
  EXPECT_EQ(o.keys.at("thermal.T_in"), "900");
  EXPECT_EQ(o.keys.at("thermal.flux.q_film"), "3e5");
}

TEST(CaseOverrides, AKeyIsCheckedByItsOwnReader) {
  const config::CaseFile cf = config::read_case_file(CENTREC_SOURCE_DIR "/cases/quickstart.yaml");
  config::Overrides o;
  o.keys["dem.contacts.wall_rolling_model"] = "liggghts";
  o.keys["thermal.T_in"] = "900";
  const config::CaseFile with = config::with_overrides(cf, o);
  EXPECT_EQ(cf.dem->scene.wall_rolling, dem::WallRolling::relative);
  EXPECT_EQ(with.dem->scene.wall_rolling, dem::WallRolling::liggghts);
  EXPECT_EQ(with.thermal->model.T_in, 900.0);
  EXPECT_EQ(config::resolved_value(with, "thermal.T_in"), "900");
  EXPECT_EQ(config::resolved_value(with, "dem.contacts.wall_rolling_model"), "liggghts");
  // Applied twice, the same case.
  EXPECT_EQ(config::with_overrides(with, o).resolved_yaml, with.resolved_yaml);

  const auto refusal = [&](const std::string& key, const std::string& value) {
    config::Overrides bad;
    bad.keys[key] = value;
    try {
      config::with_overrides(cf, bad);
    } catch (const config::ConfigError& e) {
      std::printf("%s=%s: %s\n", key.c_str(), value.c_str(), e.what());
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("dem.run.threads", "5000").find("dem.run.threads"), std::string::npos);    // out of range
  EXPECT_NE(refusal("dem.run.threads", "two").find("dem.run.threads"), std::string::npos);     // not an integer
  EXPECT_NE(refusal("thermal.T_inn", "900").find("T_in"), std::string::npos);                  // did you mean
  EXPECT_NE(refusal("sweep.speed_rpm", "50").find("no `sweep:` section"), std::string::npos);  // absent section
  EXPECT_NE(refusal("thermal", "900").find("not a key path"), std::string::npos);
  EXPECT_NE(refusal("thermal.T_in.x", "900").find("not a section"), std::string::npos);
}

TEST(CaseOverrides, TheOperatingPointIsRecordedInTheResolvedCase) {
  // --speed-rpm and --mass-flow (every sweep point, operate's check) replace the receiver's
  // operating point: the resolved case (embedded in summary.json and dem.h5, compared by
  // --dem-from) records the point that ran, not the case file's. Without a receiver they
  // are the DEM drum's speed and its feed (or a slice's target flow).
  const config::CaseFile cf = config::read_case_file(CENTREC_SOURCE_DIR "/cases/receiver_1m.yaml");
  config::Overrides o;
  o.speed_rpm = 59.0;
  o.mass_flow = 0.4;
  const config::CaseFile with = config::with_overrides(cf, o);
  std::printf("receiver_1m at --speed-rpm 59 --mass-flow 0.4: receiver.speed_rpm %s, receiver.mass_flow %s\n",
              config::resolved_value(with, "receiver.speed_rpm").c_str(),
              config::resolved_value(with, "receiver.mass_flow").c_str());
  EXPECT_EQ(config::resolved_value(with, "receiver.speed_rpm"), "59");
  EXPECT_EQ(config::resolved_value(with, "receiver.mass_flow"), "0.4");
  EXPECT_DOUBLE_EQ(with.receiver->op.mass_flow, 0.4);
  // The DEM it derives is the one the flags give on the case file.
  const auto a = config::effective_dem(*with.dem, &*with.receiver, o);
  const auto b = config::effective_dem(*cf.dem, &*cf.receiver, o);
  EXPECT_EQ(a.scene.drum.omega, b.scene.drum.omega);
  EXPECT_EQ(a.scene.slice.target_mass_flow, b.scene.slice.target_mass_flow);
  // An odd value keeps every bit.
  o.speed_rpm = 55.454000000000001;
  o.mass_flow = 0.1 + 0.2;
  const config::CaseFile odd = config::with_overrides(cf, o);
  EXPECT_EQ(odd.receiver->op.mass_flow, 0.1 + 0.2);

  // No receiver: a periodic slice of its own drum.
  const config::CaseFile slice = config::read_case_file(CENTREC_SOURCE_DIR "/cases/d12_slice.yaml");
  ASSERT_FALSE(slice.receiver);
  config::Overrides s;
  s.speed_rpm = 150.0;
  s.mass_flow = 0.03;
  const config::CaseFile ws = config::with_overrides(slice, s);
  EXPECT_EQ(config::resolved_value(ws, "dem.drum.speed_rpm"), "150");
  EXPECT_EQ(config::resolved_value(ws, slice.dem->scene.slice.enabled ? "dem.slice.target_mass_flow" : "dem.feeder.mass_flow"),
            "0.03");
}
