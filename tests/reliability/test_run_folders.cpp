// A run folder is never overwritten or mixed (io/run_folder.hpp, docs/outputs.md "Run
// folders"): a second run into the folder of another is refused and leaves its files as they
// were; --overwrite replaces them all; an interrupted run's folder says how to resume it; a
// folder another live process writes into is refused even with --overwrite, one whose
// process is gone is taken over; --resume with an --out elsewhere is refused. Each case
// fails on a binary without the claim (it wrote over the first run, or resumed silently).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "run_binary.hpp"
#include "tests/test_case_dir.hpp"

namespace fs = std::filesystem;
using centrec::testing::run_binary;

namespace {
const std::string kSource = CENTREC_SOURCE_DIR;
const std::string kUniform = kSource + "/cases/thermal_centrec_uniform.yaml";
const std::string kGaussian = kSource + "/cases/thermal_centrec_gaussian_1d.yaml";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(RunFolders, ASecondRunIntoAnotherRunsFolderIsRefusedAndOverwriteReplacesIt) {
  const std::string dir = centrec::testing::temp_dir("run_folders") + "/D";
  ASSERT_EQ(run_binary({"thermal", kUniform, "--out", dir}).exit_code, 0);
  const std::string first = slurp(dir + "/summary.json");
  const auto second = run_binary({"thermal", kGaussian, "--out", dir});
  std::printf("second run: exit %d: %s", second.exit_code, second.err.c_str());
  EXPECT_NE(second.exit_code, 0);
  EXPECT_NE(second.err.find("holds the results of an earlier run"), std::string::npos);
  EXPECT_NE(second.err.find("--overwrite"), std::string::npos);
  EXPECT_EQ(slurp(dir + "/summary.json"), first);  // the first run's results untouched
  EXPECT_FALSE(fs::exists(dir + "/.centrec-run.lock"));
  // --overwrite: the second run's files, none of the first's.
  std::ofstream(dir + "/losses.png") << "a figure of the first run";
  const auto over = run_binary({"thermal", kGaussian, "--out", dir, "--overwrite"});
  ASSERT_EQ(over.exit_code, 0) << over.err;
  EXPECT_NE(slurp(dir + "/summary.json"), first);
  EXPECT_NE(slurp(dir + "/summary.json").find("thermal_centrec_gaussian_1d"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/losses.png"));
  EXPECT_FALSE(fs::exists(dir + "/.centrec-run.lock"));
  fs::remove_all(fs::path(dir).parent_path());
}

TEST(RunFolders, AnInterruptedRunsFolderSaysHowToResumeIt) {
  const std::string dir = centrec::testing::temp_dir("run_folders_ck") + "/D";
  fs::create_directories(dir);
  std::ofstream(dir + "/checkpoint.h5") << "the checkpoint of an interrupted run";
  const auto r = run_binary({"dem", kSource + "/tests/outputs/tiny_drum.yaml", "--out", dir, "--no-plots"});
  std::printf("exit %d: %s", r.exit_code, r.err.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("interrupted run"), std::string::npos);
  EXPECT_NE(r.err.find("centrec dem --resume " + dir), std::string::npos);
  EXPECT_EQ(slurp(dir + "/checkpoint.h5"), "the checkpoint of an interrupted run");
  fs::remove_all(fs::path(dir).parent_path());
}

TEST(RunFolders, AFolderInUseIsRefusedEvenWithOverwriteAndAStaleLockIsTakenOver) {
  const std::string dir = centrec::testing::temp_dir("run_folders_lock") + "/D";
  fs::create_directories(dir);
  // This test process is alive: its lock holds the folder.
  std::ofstream(dir + "/.centrec-run.lock") << "pid " << ::getpid() << "\ncommand centrec dem a_long_run.yaml\n";
  const auto busy = run_binary({"thermal", kUniform, "--out", dir, "--overwrite"});
  std::printf("exit %d: %s", busy.exit_code, busy.err.c_str());
  EXPECT_NE(busy.exit_code, 0);
  EXPECT_NE(busy.err.find("in use by another centrec run"), std::string::npos);
  EXPECT_NE(busy.err.find("a_long_run.yaml"), std::string::npos);
  // The message names the lock to remove if that process is no centrec run.
  EXPECT_NE(busy.err.find("remove " + dir + "/.centrec-run.lock)"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/summary.json"));
  // A lock whose process is gone (a run killed with -9): the folder is judged by its files.
  const pid_t gone = ::fork();
  if (gone == 0) ::_exit(0);
  ::waitpid(gone, nullptr, 0);
  std::ofstream(dir + "/.centrec-run.lock") << "pid " << gone << "\ncommand centrec thermal x.yaml\n";
  const auto taken = run_binary({"thermal", kUniform, "--out", dir});
  EXPECT_EQ(taken.exit_code, 0) << taken.err;
  EXPECT_TRUE(fs::exists(dir + "/summary.json"));
  EXPECT_FALSE(fs::exists(dir + "/.centrec-run.lock"));
  fs::remove_all(fs::path(dir).parent_path());
}

TEST(RunFolders, ResumeWithAnotherOutIsRefused) {
  const std::string dir = centrec::testing::temp_dir("run_folders_resume");
  const auto r = run_binary({"dem", "--resume", dir + "/A", "--out", dir + "/B"});
  std::printf("exit %d: %s", r.exit_code, r.err.c_str());
  EXPECT_EQ(r.exit_code, 2);  // a usage error
  EXPECT_NE(r.err.find("--resume " + dir + "/A continues the run in that folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/B"));
  fs::remove_all(dir);
}

TEST(RunFolders, ASweepGridWithARepeatedPointIsRefused) {
  const std::string dir = centrec::testing::temp_dir("run_folders_sweep");
  std::string text = slurp(kSource + "/tests/coupling/small_coupled.yaml");
  text += "sweep: {speed_rpm: [160.08, 160.08], mass_flow: [0.0357]}\n";
  std::ofstream(dir + "/case.yaml") << text;
  const auto r = run_binary({"sweep", dir + "/case.yaml", "--out", dir + "/S", "--allow-small-drum"});
  std::printf("exit %d: %s", r.exit_code, r.err.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("twice"), std::string::npos);
  fs::remove_all(dir);
}

TEST(RunFolders, ADeckIsNotWrittenIntoARunOrOverAnotherDeck) {
  // export-liggghts claims its folder as the runs do: not into another run's results, not over
  // an earlier (perhaps hand-edited) deck unless --overwrite, which replaces it whole.
  const std::string dir = centrec::testing::temp_dir("run_folders_deck");
  const std::string kCase = kSource + "/tests/liggghts/small_drum.yaml";
  ASSERT_EQ(run_binary({"thermal", kUniform, "--out", dir + "/R"}).exit_code, 0);
  const auto into_run = run_binary({"export-liggghts", kCase, "--out", dir + "/R"});
  std::printf("into a run's folder: exit %d: %s", into_run.exit_code, into_run.err.c_str());
  EXPECT_NE(into_run.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir + "/R/in.centrec"));
  ASSERT_EQ(run_binary({"export-liggghts", kCase, "--out", dir + "/deck"}).exit_code, 0);
  std::ofstream(dir + "/deck/in.centrec", std::ios::app) << "# edited by hand\n";
  const std::string edited = slurp(dir + "/deck/in.centrec");
  const auto again = run_binary({"export-liggghts", kCase, "--out", dir + "/deck"});
  std::printf("over a deck: exit %d: %s", again.exit_code, again.err.c_str());
  EXPECT_NE(again.exit_code, 0);
  EXPECT_EQ(slurp(dir + "/deck/in.centrec"), edited);
  ASSERT_EQ(run_binary({"export-liggghts", kCase, "--out", dir + "/deck", "--overwrite"}).exit_code, 0);
  EXPECT_EQ(slurp(dir + "/deck/in.centrec").find("# edited by hand"), std::string::npos);
  fs::remove_all(dir);
}

TEST(RunFolders, AFinishedRunIsNotResumed) {
  // A finished run keeps its checkpoint (a settled start reads it): --resume ran its last
  // stretch again and rewrote its results without a word.
  const std::string dir = centrec::testing::temp_dir("run_folders_finished") + "/D";
  ASSERT_EQ(run_binary({"dem", kSource + "/tests/outputs/tiny_drum.yaml", "--out", dir, "--no-plots", "--set",
                        "dem.run.checkpoint_interval=300"},
                       120.0)
                .exit_code,
            0);
  ASSERT_TRUE(fs::exists(dir + "/checkpoint.h5"));
  const std::string summary = slurp(dir + "/summary.json");
  const auto r = run_binary({"dem", "--resume", dir, "--no-plots"}, 120.0);
  std::printf("exit %d: %s", r.exit_code, r.err.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("holds a finished run"), std::string::npos);
  EXPECT_EQ(slurp(dir + "/summary.json"), summary);
  fs::remove_all(fs::path(dir).parent_path());
}
