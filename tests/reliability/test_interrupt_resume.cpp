// Ctrl-C loses nothing (docs/reliability.md): `centrec dem` sent SIGINT at a random
// moment (fixed seed) writes a checkpoint at its next safe point, says how to resume and
// exits with 128 + 2; `centrec dem --resume` then ends bitwise identical to the run left
// alone, with the first run's --duration (kept in the checkpoint) and a summary.json that
// reports it. A SIGKILL inside a sampled turn loses at most one snapshot interval: the
// run checkpoints between the turn's snapshots, and resumes from there bitwise.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>

#include "io/checkpoint_h5.hpp"
#include "io/h5_file.hpp"
#include "io/particle_tracks_h5.hpp"
#include "tests/reliability/run_binary.hpp"
#include "tests/scene/resume_case.hpp"
#include "tests/test_case_dir.hpp"

using centrec::testing::BinaryRun;
using centrec::testing::run_binary;

namespace {

// The small fed drum of the resume tests with a long run.duration that --duration
// shortens; checkpoints only at the end and at the interrupt.
std::string interrupt_case() {
  std::string text = centrec::testing::kResumeCase;
  text.replace(text.find("duration: 0.04"), 14, "duration: 5.00");
  text.replace(text.find("checkpoint_interval: 1.0e-9"), 27, "checkpoint_interval: 0");
  return text;
}

std::vector<double> dataset(const std::string& dir, const std::string& path) {
  return centrec::io::H5File::open_read(dir + "/dem.h5").read(path);
}

// The datasets `paths` of a/dem.h5 and b/dem.h5 compared value by value, bitwise (NaN, an
// empty bin, in both is skipped). Returns how many values are equal; 0 after a difference,
// which fails the test naming it.
std::size_t bitwise_equal_values(const std::string& a, const std::string& b, const std::vector<const char*>& paths) {
  std::size_t equal = 0;
  for (const char* p : paths) {
    const auto x = dataset(a, p), y = dataset(b, p);
    if (x.size() != y.size()) {
      ADD_FAILURE() << p << ": " << x.size() << " values vs " << y.size();
      return 0;
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i] != x[i] && y[i] != y[i]) continue;
      if (std::memcmp(&x[i], &y[i], sizeof(double)) != 0) {
        ADD_FAILURE() << p << "[" << i << "]: " << x[i] << " vs " << y[i];
        return 0;
      }
      ++equal;
    }
  }
  return equal;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(InterruptResume, SigintCheckpointsAndTheResumedRunEqualsTheWholeOne) {
  const std::string dir = centrec::testing::fresh_dir("interrupt");
  const std::string case_path = centrec::testing::write_case(dir, interrupt_case());
  const std::string whole = dir + "/whole", stopped = dir + "/stopped";
  const auto t0 = std::chrono::steady_clock::now();
  const BinaryRun w = run_binary({"dem", case_path, "--out", whole, "--duration", "0.06", "--no-plots"}, 300.0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(w.exit_code, 0) << w.err;

  // SIGINT somewhere in the spin-up or the first sampled turn, counted from the spin-up's
  // start (before it the default action applies; the whole run's wall time is a measure of
  // the run, not of the next one, which may run alone or beside other tests).
  std::mt19937_64 rng(28);
  const double at = std::uniform_real_distribution<double>(0.05, 0.3)(rng) * wall;
  const BinaryRun s =
      run_binary({"dem", case_path, "--out", stopped, "--duration", "0.06", "--no-plots"}, 300.0, at, 0, "spin-up:");
  std::printf("whole run %.2f s of wall time; SIGINT %.2f s after the spin-up began; stderr:\n%s\n", wall, at,
              s.err.c_str());
  ASSERT_EQ(s.exit_code, 130) << s.err;
  EXPECT_NE(s.err.find("stopped by SIGINT at t = "), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("continue with: centrec dem --resume " + stopped), std::string::npos) << s.err;
  ASSERT_TRUE(std::filesystem::exists(stopped + "/checkpoint.h5"));
  EXPECT_FALSE(std::filesystem::exists(stopped + "/summary.json"));

  // --duration cannot change the resumed run (it is stored), and the resumed run keeps it.
  const BinaryRun again = run_binary({"dem", "--resume", stopped, "--duration", "1"}, 30.0);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("continues to the run.duration stored in"), std::string::npos) << again.err;
  const BinaryRun r = run_binary({"dem", "--resume", stopped}, 300.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const std::size_t compared =
      bitwise_equal_values(whole, stopped, {"/mass_flow/time", "/mass_flow/fed", "/mass_flow/out", "/mass_flow/holdup",
                                            "/film/thickness_mean", "/film/axial_velocity_mean", "/film/solid_fraction_mean"});
  EXPECT_GT(compared, 100u);
  // summary.json reports what ran: the --duration of the first command.
  const std::string summary = slurp(stopped + "/summary.json");
  EXPECT_NE(summary.find("duration: 0.06"), std::string::npos);
  EXPECT_EQ(summary.find("duration: 5"), std::string::npos);  // the case file's
  const double t_end = dataset(stopped, "/mass_flow/time").back();
  EXPECT_LT(t_end, 0.5);  // 0.06 s + 2 turns of 0.187 s, not 5 s
  std::printf("%zu values bitwise equal; the resumed run ended at t = %.4f s\n", compared, t_end);
  std::filesystem::remove_all(dir);
}

namespace {
// Starts `centrec dem CASE --out DIR --no-plots` and SIGKILLs it once its checkpoint satisfies
// `reached`. False if the run ended first, or the checkpoint left behind does not satisfy it.
bool kill_at_checkpoint(const std::string& case_path, const std::string& dir,
                        const std::function<bool(const centrec::io::RunCheckpoint&)>& reached) {
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execl(CENTREC_BINARY, CENTREC_BINARY, "dem", case_path.c_str(), "--out", dir.c_str(), "--no-plots",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  bool inside = false;
  for (int k = 0; k < 60000 && !inside; ++k) {
    if (::waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    try {
      inside = reached(centrec::io::read_checkpoint(dir));
    } catch (const std::exception&) {
    }
  }
  ::kill(child, SIGKILL);
  ::waitpid(child, &status, 0);
  return inside && WIFSIGNALED(status) && reached(centrec::io::read_checkpoint(dir));
}

// Killed once a checkpoint inside its first sampled turn exists (after `snapshots` of the
// turn's snapshots).
bool kill_inside_the_first_sampled_turn(const std::string& case_path, const std::string& dir, int snapshots) {
  return kill_at_checkpoint(case_path, dir, [&](const centrec::io::RunCheckpoint& ck) {
    return ck.phase == "sampling" && ck.turn_snapshots >= snapshots;
  });
}

// The last progress line's "t = DONE of TOTAL s".
bool last_progress(const std::string& err, double& done, double& total) {
  const std::size_t at = err.rfind(" t = ");
  return at != std::string::npos && std::sscanf(err.c_str() + at, " t = %lf of %lf s", &done, &total) == 2;
}
}  // namespace

TEST(InterruptResume, SigkillInsideASampledTurnResumesFromThatTurnBitwise) {
  // One long sampled turn of 8 snapshots, a checkpoint at every safe point.
  std::string text = centrec::testing::kResumeCase;
  const std::string two_turns = "turns: 2, snapshots_per_turn: 4";
  text.replace(text.find(two_turns), two_turns.size(), "turns: 1, snapshots_per_turn: 8");
  const std::string dir = centrec::testing::fresh_dir("interrupt_turn");
  const std::string case_path = centrec::testing::write_case(dir, text);
  const std::string whole = dir + "/whole", killed = dir + "/killed";
  const BinaryRun w = run_binary({"dem", case_path, "--out", whole, "--no-plots"}, 300.0);
  ASSERT_EQ(w.exit_code, 0) << w.err;

  // SIGKILL once a checkpoint inside the turn exists (after its 3rd snapshot).
  ASSERT_TRUE(kill_inside_the_first_sampled_turn(case_path, killed, 3))
      << "no checkpoint inside the sampled turn before the run ended";
  const auto ck = centrec::io::read_checkpoint(killed);
  const double period = 60.0 / 320.16, t_turn_end = dataset(whole, "/mass_flow/time").back();
  const double t_ck = ck.scene.engine.time;
  std::printf("killed with a checkpoint at t = %.5f s, %d of 8 snapshots into the turn (turn ends at %.5f s)\n", t_ck,
              ck.turn_snapshots, t_turn_end);
  EXPECT_EQ(ck.sampled_turns, 0);
  EXPECT_GE(ck.turn_snapshots, 3);
  EXPECT_LT(t_ck, t_turn_end - 0.5 * period / 8);  // the only turn ends the run

  const BinaryRun r = run_binary({"dem", "--resume", killed, "--no-plots"}, 300.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("(sampling)"), std::string::npos) << r.err;
  const std::size_t compared =
      bitwise_equal_values(whole, killed, {"/mass_flow/time", "/mass_flow/fed", "/mass_flow/out", "/mass_flow/holdup",
                                           "/film/thickness_mean", "/film/axial_velocity_mean",
                                           "/film/solid_fraction_mean", "/film/dispersion"});
  EXPECT_GT(compared, 100u);
  std::printf("%zu values bitwise equal to the run left alone\n", compared);

  // The particle tracks: every one of the turn's 8 snapshots, those before the kill from the
  // part written with the checkpoint, the same bits as the run left alone.
  const auto tw = centrec::io::read_tracks(whole), tk = centrec::io::read_tracks(killed);
  ASSERT_EQ(tw.size(), 8u);
  ASSERT_EQ(tk.size(), tw.size());
  std::size_t records = 0;
  for (std::size_t s = 0; s < tw.size(); ++s) {
    EXPECT_EQ(tk[s].time, tw[s].time) << "snapshot " << s;
    EXPECT_EQ(tk[s].id, tw[s].id) << "snapshot " << s;
    EXPECT_EQ(tk[s].z, tw[s].z) << "snapshot " << s;
    EXPECT_EQ(tk[s].r, tw[s].r) << "snapshot " << s;
    records += tw[s].id.size();
  }
  EXPECT_GT(records, 8 * 400u);
  std::size_t parts = 0;
  for (const auto& e : std::filesystem::directory_iterator(centrec::io::tracks_dir(killed))) parts += e.is_regular_file();
  EXPECT_GE(parts, 2u);  // one part before the kill, at least one after the resume
  std::printf("tracks: %zu snapshots, %zu particle records, bitwise equal (%zu parts in the resumed run)\n", tw.size(),
              records, parts);
  std::filesystem::remove_all(dir);
}

namespace {
// The one entry CACHE/<key> a coupled run made.
std::string cache_entry(const std::string& cache) {
  for (const auto& e : std::filesystem::directory_iterator(cache))
    if (e.is_directory() && e.path().filename().string().find(".tmp") == std::string::npos) return e.path().string();
  return "";
}
}  // namespace

TEST(InterruptResume, SigintDuringTheDemOfARunAndTheSameCommandAgainEqualsTheWholeRun) {
  const std::string dir = centrec::testing::fresh_dir("interrupt_run");
  const std::string kCase = CENTREC_SOURCE_DIR "/tests/coupling/small_coupled.yaml";
  const auto t0 = std::chrono::steady_clock::now();
  const BinaryRun w = run_binary({"run", kCase, "--out", dir + "/whole", "--cache", dir + "/cache_whole", "--no-plots", "--allow-small-drum", "--allow-unsteady"}, 600.0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(w.exit_code, 0) << w.err;

  std::mt19937_64 rng(2828);
  const double at = std::uniform_real_distribution<double>(0.05, 0.25)(rng) * wall;
  const std::vector<std::string> cmd = {"run", kCase, "--out", dir + "/stopped", "--cache", dir + "/cache", "--no-plots", "--allow-small-drum", "--allow-unsteady"};
  const BinaryRun s = run_binary(cmd, 600.0, at, 0, "spin-up:");
  std::printf("whole run %.2f s; SIGINT %.2f s after its DEM's spin-up began; stderr:\n%s\n", wall, at, s.err.c_str());
  ASSERT_EQ(s.exit_code, 130) << s.err;
  EXPECT_NE(s.err.find("continue with the same command"), std::string::npos) << s.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/stopped")) << "the empty output folder was left behind";
  const BinaryRun r = run_binary(cmd, 600.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("continuing the interrupted DEM run"), std::string::npos) << r.err;

  const std::string a = cache_entry(dir + "/cache_whole"), b = cache_entry(dir + "/cache");
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  const std::size_t compared =
      bitwise_equal_values(a, b, {"/mass_flow/time", "/mass_flow/out", "/film/thickness_mean", "/film/axial_velocity_mean"});
  EXPECT_GT(compared, 50u);
  const auto ta = centrec::io::H5File::open_read(dir + "/whole/results.h5").read("/steady/T");
  const auto tb = centrec::io::H5File::open_read(dir + "/stopped/results.h5").read("/steady/T");
  ASSERT_EQ(ta.size(), tb.size());
  EXPECT_EQ(std::memcmp(ta.data(), tb.data(), ta.size() * sizeof(double)), 0);
  std::filesystem::remove_all(dir);
}

TEST(InterruptResume, AResumedSamplingPhaseCountsItsProgressToTheRunsEnd) {
  // A spin-up extended past run.duration (a flow never steady to 1e-6), then one sampled
  // turn of 8 snapshots: the sampling starts later than run.duration.
  std::string text = centrec::testing::kResumeCase;
  const std::string two_turns = "turns: 2, snapshots_per_turn: 4";
  text.replace(text.find(two_turns), two_turns.size(), "turns: 1, snapshots_per_turn: 8");
  text.replace(text.find("progress_interval: 1000"), 23,
               "progress_interval: 1000, steady_tolerance: 1.0e-6, max_extension: 0.02");
  const std::string dir = centrec::testing::fresh_dir("resume_progress");
  const std::string case_path = centrec::testing::write_case(dir, text);
  const std::string killed = dir + "/killed";
  ASSERT_TRUE(kill_inside_the_first_sampled_turn(case_path, killed, 3)) << "no checkpoint inside the sampled turn";
  const double t_ck = centrec::io::read_checkpoint(killed).scene.engine.time;
  EXPECT_GT(t_ck, 0.06 - 1e-9);  // sampling began after the extension

  const BinaryRun r = run_binary({"dem", "--resume", killed, "--no-plots"}, 300.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double done = 0.0, total = 0.0;
  ASSERT_TRUE(last_progress(r.err, done, total)) << r.err;
  const double t_end = dataset(killed, "/mass_flow/time").back();
  std::printf("resumed at t = %.5f s; last progress line: t = %.4f of %.4f s; the run ended at %.5f s\n", t_ck, done,
              total, t_end);
  EXPECT_NEAR(done, t_end, 1e-3);
  EXPECT_NEAR(total, t_end, 1e-3) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(InterruptResume, ASpinUpResumedWithALongerExtensionAndMoreTurnsEqualsTheWholeLongerRun) {
  // A flow never steady to 1e-6: the spin-up runs to its cap. The first run may extend by
  // 0.05 s and sample 1 turn; it is killed inside its extension and resumed with 0.1 s and 2
  // turns, which must equal a run started with those.
  std::string text = centrec::testing::kResumeCase;
  text.replace(text.find("progress_interval: 1000"), 23,
               "progress_interval: 1000, steady_tolerance: 1.0e-6, max_extension: 0.05");
  text.replace(text.find("turns: 2,"), 9, "turns: 1,");
  const std::string dir = centrec::testing::fresh_dir("resume_longer");
  const std::string case_path = centrec::testing::write_case(dir, text);
  const std::string whole = dir + "/whole", killed = dir + "/killed";
  const BinaryRun w = run_binary({"dem", case_path, "--out", whole, "--no-plots", "--set", "dem.run.max_extension=0.1",
                                  "--set", "dem.sampling.turns=2"},
                                 300.0);
  ASSERT_EQ(w.exit_code, 0) << w.err;
  ASSERT_TRUE(kill_at_checkpoint(case_path, killed, [](const centrec::io::RunCheckpoint& ck) {
    return ck.phase == "spin-up" && ck.scene.engine.time > 0.045;
  })) << "no checkpoint inside the extension";
  const double t_ck = centrec::io::read_checkpoint(killed).scene.engine.time;

  // Too short an extension for the checkpoint's time is refused, naming both times.
  const BinaryRun shorter = run_binary({"dem", "--resume", killed, "--set", "dem.run.max_extension=0.001"}, 30.0);
  EXPECT_EQ(shorter.exit_code, 2) << shorter.err;
  EXPECT_NE(shorter.err.find("before the checkpoint's t ="), std::string::npos) << shorter.err;

  const BinaryRun r = run_binary({"dem", "--resume", killed, "--no-plots", "--set", "dem.run.max_extension=0.1", "--set",
                                  "dem.sampling.turns=2"},
                                 300.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t compared =
      bitwise_equal_values(whole, killed, {"/mass_flow/time", "/mass_flow/fed", "/mass_flow/out", "/mass_flow/holdup",
                                           "/film/thickness_mean", "/film/axial_velocity_mean",
                                           "/film/solid_fraction_mean"});
  const double t_end = dataset(killed, "/mass_flow/time").back(), period = 60.0 / 320.16;
  std::printf("killed at t = %.4f s in the extension; resumed to t = %.4f s; %zu values bitwise equal to the longer "
              "run left alone\n",
              t_ck, t_end, compared);
  EXPECT_GT(compared, 100u);
  EXPECT_NEAR(t_end, 0.04 + 0.1 + 2 * period, 0.01);  // the longer cap and two turns, not 0.09 s + one
  EXPECT_NE(slurp(killed + "/summary.json").find("max_extension: 0.1"), std::string::npos);

  // Once sampling has begun (here: a finished run), the spin-up can no longer be lengthened.
  const BinaryRun late = run_binary({"dem", "--resume", whole, "--set", "dem.sampling.turns=3"}, 30.0);
  EXPECT_EQ(late.exit_code, 2) << late.err;
  EXPECT_NE(late.err.find("only while it spins up"), std::string::npos) << late.err;
  std::filesystem::remove_all(dir);
}
