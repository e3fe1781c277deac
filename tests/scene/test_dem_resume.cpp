// `centrec dem --resume`: a run killed (SIGKILL) during sampling and resumed from its
// checkpoint ends bitwise identical to the same run left alone (mass flows, film fields,
// holdup); a damaged checkpoint and a case that does not match it are refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "cli/commands.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/h5_file.hpp"
#include "tests/scene/resume_case.hpp"
#include "tests/scene/slice_case.hpp"
#include "tests/test_case_dir.hpp"

using namespace centrec;
using namespace centrec::cli;
using namespace centrec::io;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

namespace {

const char* const kCase = centrec::testing::kResumeCase;

// Runs `centrec dem` in a child process and SIGKILLs it once its checkpoint says it has
// sampled at least one turn. Returns the sampled turns of the checkpoint left behind.
int run_and_kill(const std::string& case_path, const std::string& out) {
  const pid_t child = ::fork();
  if (child == 0) {
    int rc = 1;
    try {
      rc = cmd_dem({case_path, "--out", out, "--no-plots"});
    } catch (...) {
    }
    ::_exit(rc);
  }
  for (int k = 0; k < 60000; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!std::filesystem::exists(checkpoint_path(out))) continue;
    try {
      if (read_checkpoint(out).sampled_turns >= 1) break;
    } catch (const std::exception&) {
    }
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status)) << "the child finished before it was killed";
  return read_checkpoint(out).sampled_turns;
}

std::vector<double> dataset(const std::string& dir, const std::string& path) {
  return io::H5File::open_read(dir + "/dem.h5").read(path);
}

}  // namespace

// First in the file: fork() before this process has started any OpenMP threads.
TEST(DemResume, KilledAndResumedRunEqualsUninterruptedRun) {
  const std::string dir = temp_dir("resume");
  const std::string case_path = write_case(dir, kCase);
  const std::string killed = dir + "/killed", whole = dir + "/whole";
  const int at = run_and_kill(case_path, killed);
  std::printf("killed after %d sampled turn(s); resuming\n", at);
  EXPECT_FALSE(std::filesystem::exists(killed + "/summary.json"));
  ASSERT_EQ(cmd_dem({"--resume", killed, "--no-plots"}), 0);
  ASSERT_EQ(cmd_dem({case_path, "--out", whole, "--no-plots"}), 0);

  std::size_t compared = 0;
  for (const char* p : {"/mass_flow/time", "/mass_flow/fed", "/mass_flow/out", "/mass_flow/holdup",
                        "/film/thickness_mean", "/film/axial_velocity_mean", "/film/axial_velocity_std",
                        "/film/solid_fraction_mean", "/film/dispersion"}) {
    const auto a = dataset(whole, p), b = dataset(killed, p);
    ASSERT_EQ(a.size(), b.size()) << p;
    ASSERT_GT(a.size(), 0u) << p;
    for (std::size_t i = 0; i < a.size(); ++i) {
      // NaN marks empty bins in both; anything else must match bitwise.
      if (a[i] != a[i] && b[i] != b[i]) continue;
      ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof(double)), 0) << p << "[" << i << "]: " << a[i] << " vs " << b[i];
      ++compared;
    }
  }
  const auto fa = io::H5File::open_read(whole + "/dem.h5"), fb = io::H5File::open_read(killed + "/dem.h5");
  const double ta = fa.number_attribute("/film", "mean_thickness_m"), tb = fb.number_attribute("/film", "mean_thickness_m");
  std::printf("%zu values compared bitwise; film thickness %.9g m (uninterrupted) vs %.9g m (resumed)\n", compared,
              ta, tb);
  EXPECT_EQ(ta, tb);
  EXPECT_GT(ta, 0.0);
  std::filesystem::remove_all(dir);
}

TEST(DemResume, RefusesDamagedOrMismatchedCheckpoints) {
  const std::string dir = temp_dir("resume_bad");
  std::string text = kCase;
  text.replace(text.find("turns: 2,"), 9, "turns: 0,");  // spin-up only: quick
  text.replace(text.find("duration: 0.04"), 14, "duration: 0.01");
  const std::string case_path = write_case(dir, text);
  const std::string out = dir + "/run";
  ASSERT_EQ(cmd_dem({case_path, "--out", out, "--no-plots"}), 0);
  ASSERT_NO_THROW(read_checkpoint(out));

  // A case that differs from the stored one.
  std::string other = text;
  other.replace(other.find("mass_flow: 4.0e-3"), 17, "mass_flow: 5.0e-3");
  const std::string other_path = dir + "/other.yaml";
  std::ofstream(other_path) << other;
  try {
    cmd_dem({other_path, "--resume", out});
    ADD_FAILURE() << "a mismatched case was accepted";
  } catch (const std::invalid_argument& e) {
    std::printf("mismatch: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("does not match"), std::string::npos);
  }

  // Damage: overwrite bytes in the middle of the file.
  const std::string ck = checkpoint_path(out);
  const auto size = std::filesystem::file_size(ck);
  {
    std::fstream f(ck, std::ios::in | std::ios::out | std::ios::binary);
    const std::string junk(64, '\x5a');
    for (int q = 1; q <= 3; ++q) {
      f.seekp(static_cast<std::streamoff>(size * q / 4));
      f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
    }
  }
  try {
    cmd_dem({"--resume", out});
    ADD_FAILURE() << "a damaged checkpoint was accepted";
  } catch (const std::runtime_error& e) {
    std::printf("damaged: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("cannot resume"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

// The slice controller's state and the slice flow log survive checkpoint.h5 exactly.
TEST(DemResume, ControlledSliceStateRoundTripsThroughTheCheckpointFile) {
  dem::scene::SceneConfig c = centrec::testing::controlled_slice(500, 5e-3);
  c.slice.controller_window_turns = 0.1;
  c.threads = 1;
  dem::scene::CentrecScene scene(c);
  scene.advance(0.04);  // two controller windows
  ASSERT_GE(scene.controller_log().size(), 2u);
  scene.simulation().rebuild_lists();
  RunCheckpoint ck;
  ck.phase = "spin-up";
  ck.resolved_yaml = "dem: {}";
  ck.scene = scene.export_state();
  const std::string dir = temp_dir("controller_state");
  write_checkpoint(dir, ck);
  const RunCheckpoint back = read_checkpoint(dir);
  const auto& a = ck.scene.controller;
  const auto& b = back.scene.controller;
  ASSERT_TRUE(back.scene.has_controller);
  EXPECT_EQ(a.rng, b.rng);
  EXPECT_EQ(a.size_rng, b.size_rng);
  EXPECT_EQ(a.window_start, b.window_start);
  EXPECT_EQ(a.flow_sum, b.flow_sum);
  EXPECT_EQ(a.flow_samples, b.flow_samples);
  ASSERT_EQ(a.log.size(), b.log.size());
  for (std::size_t k = 0; k < a.log.size(); ++k) {
    EXPECT_EQ(a.log[k].mass_flow, b.log[k].mass_flow);
    EXPECT_EQ(a.log[k].particles, b.log[k].particles);
    EXPECT_EQ(a.log[k].change, b.log[k].change);
  }
  ASSERT_EQ(ck.scene.mass_flow_log.size(), back.scene.mass_flow_log.size());
  EXPECT_EQ(ck.scene.mass_flow_log.back().axial_flow, back.scene.mass_flow_log.back().axial_flow);
  EXPECT_NE(back.scene.mass_flow_log.back().axial_flow, 0.0);
  // A scene resumed from it continues like the original.
  dem::scene::CentrecScene resumed(c, back.scene);
  scene.advance(0.02);
  resumed.advance(0.02);
  EXPECT_EQ(scene.controller_log().size(), resumed.controller_log().size());
  EXPECT_EQ(scene.free_particles(), resumed.free_particles());
  EXPECT_EQ(scene.mass_flow_log().back().axial_flow, resumed.mass_flow_log().back().axial_flow);
  std::printf("controller windows %zu, particles %lld, slice flow %.4g kg/s (resumed: %.4g)\n",
              scene.controller_log().size(), static_cast<long long>(scene.free_particles()),
              scene.mass_flow_log().back().axial_flow, resumed.mass_flow_log().back().axial_flow);
  std::filesystem::remove_all(dir);
}

// The checkpoint keeps each pair interaction's rolling model (by name, beside the numeric
// fields) with the model's own coefficients: a CDT particle-wall interaction comes back as
// CDT, EPSD2 as EPSD2, SDS as SDS with its spring and dashpot to the bit.
TEST(DemResume, CheckpointKeepsEachInteractionsRollingModel) {
  const std::string dir = temp_dir("centrec_rolling_models");
  RunCheckpoint c;
  c.code_version = "test";
  c.phase = "spin-up";
  c.scene.engine.materials = {dem::Material{}, dem::Material{}};
  c.scene.engine.interactions = {dem::PairInteraction{0.5, 0.8, 0.2, dem::RollingModel::epsd2},
                                 dem::PairInteraction{0.4, 1e4, 0.3, dem::RollingModel::cdt},
                                 dem::PairInteraction{0.4, 1e4, 0.3, dem::RollingModel::sds, {123.456789012345, 0.1 / 3.0}},
                                 dem::PairInteraction{0.5, 0.8, 0.0, dem::RollingModel::epsd2}};
  write_checkpoint(dir, c);
  const RunCheckpoint back = read_checkpoint(dir);
  ASSERT_EQ(back.scene.engine.interactions.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const dem::PairInteraction &a = c.scene.engine.interactions[k], &b = back.scene.engine.interactions[k];
    EXPECT_TRUE(dem::same(a, b)) << "interaction " << k;
    EXPECT_EQ(static_cast<int>(b.rolling_model), static_cast<int>(a.rolling_model)) << "interaction " << k;
    EXPECT_EQ(b.rolling_coefficients, a.rolling_coefficients) << "interaction " << k;
  }
  std::printf("checkpoint rolling models: %s %s %s %s\n",
              dem::rolling_model_info(back.scene.engine.interactions[0].rolling_model).name,
              dem::rolling_model_info(back.scene.engine.interactions[1].rolling_model).name,
              dem::rolling_model_info(back.scene.engine.interactions[2].rolling_model).name,
              dem::rolling_model_info(back.scene.engine.interactions[3].rolling_model).name);
}
