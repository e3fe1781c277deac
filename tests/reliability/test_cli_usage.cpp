// Command-line misuse (docs/reliability.md): every usage error is one line on stderr naming
// the problem (exit 2), every numeric flag is checked and never silently replaced, an
// unwritable --out is refused before any work, `--version` answers.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "tests/reliability/run_binary.hpp"
#include "tests/test_case_dir.hpp"

using centrec::testing::BinaryRun;
using centrec::testing::run_binary;
using centrec::testing::temp_dir;

namespace {
const std::string kQuick = CENTREC_SOURCE_DIR "/cases/quickstart.yaml";
const std::string kThermal = CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml";

// A usage error: exit 2, nothing on stdout, one line on stderr holding `part`.
void expect_usage_error(const std::vector<std::string>& args, const std::string& part) {
  const BinaryRun r = run_binary(args, 20.0);
  std::string cmd;
  for (const auto& a : args) cmd += a + " ";
  EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.err;
  EXPECT_EQ(r.signal, 0) << cmd;
  EXPECT_NE(r.err.find(part), std::string::npos) << cmd << "\nstderr: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << cmd << "\nstderr: " << r.err;
  EXPECT_EQ(r.out, "") << cmd;
  EXPECT_EQ(r.err.find("stoi"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("stod"), std::string::npos) << r.err;
}
}  // namespace

TEST(CliUsage, MissingOutAndUnknownFlagsSayWhatIsWrong) {
  expect_usage_error({"thermal", kThermal}, "--out is required");
  expect_usage_error({"thermal"}, "no case file given");
  expect_usage_error({"validate"}, "no case file given");
  expect_usage_error({"dem", kQuick, "--threds", "2"}, "unknown option '--threds' (did you mean '--threads'?)");
  expect_usage_error({"run", kQuick, "--out", "x", "--mas-flow", "1"}, "did you mean '--mass-flow'?");
  expect_usage_error({"dem", kQuick, "--out"}, "--out");
}

TEST(CliUsage, NumericFlagsAreCheckedNotReplaced) {
  // A flag that sets a key accepts what the key accepts in a case file (an integer may be
  // written 1e3 there) and refuses the rest, naming the flag and the key.
  for (const char* v : {"100000", "-7", "1.5", "abc", "1e4"})
    expect_usage_error({"dem", kQuick, "--out", "x", "--threads", v}, "with --threads " + std::string(v) + ": ");
  expect_usage_error({"dem", kQuick, "--threads", "1.5"}, "dem.run.threads = 1.5 must be an integer");
  expect_usage_error({"dem", kQuick, "--threads", "100000"}, "out of the allowed range [0, 1024]");
  for (const char* v : {"0", "-1", "nan", "inf", "abc"})
    expect_usage_error({"dem", kQuick, "--out", "x", "--duration", v}, "--duration");
  expect_usage_error({"dem", kQuick, "--duration", "nan"}, "'nan' is not a finite number");
  for (const char* v : {"-5", "0", "nan", "1e300"})
    expect_usage_error({"run", kQuick, "--out", "x", "--speed-rpm", v}, "--speed-rpm");
  for (const char* v : {"0", "-1", "inf"})
    expect_usage_error({"run", kQuick, "--out", "x", "--mass-flow", v}, "--mass-flow");
  expect_usage_error({"run", kQuick, "--out", "x", "--threads", "-7"}, "--threads");
  // A duration the run cannot finish: refused with the reason, naming the flag.
  expect_usage_error({"dem", kQuick, "--out", "x", "--duration", "1e12"}, "with --duration 1e12: ");
}

TEST(CliUsage, VersionAndUnknownCommands) {
  const BinaryRun v = run_binary({"--version"});
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out.rfind("centrec ", 0), 0u) << v.out;
  const BinaryRun u = run_binary({"valdate", kQuick});
  EXPECT_EQ(u.exit_code, 2);
  EXPECT_NE(u.err.find("unknown command 'valdate' (did you mean 'validate'?)"), std::string::npos) << u.err;
}

TEST(CliUsage, AnUnwritableOutIsRefusedBeforeWork) {
  if (::geteuid() == 0) {
    // root writes anywhere: a file in the way of the folder stands in for no permission.
    const std::string dir = temp_dir("cli_out");
    std::ofstream(dir + "/file") << "x";
    const BinaryRun r = run_binary({"thermal", kThermal, "--out", dir + "/file"}, 20.0);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("cannot write to " + dir + "/file"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");  // refused before the solve printed anything
    return;
  }
  const std::string dir = temp_dir("cli_out");
  ::chmod(dir.c_str(), 0500);
  const BinaryRun r = run_binary({"thermal", kThermal, "--out", dir + "/out"}, 20.0);
  ::chmod(dir.c_str(), 0700);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(CliUsage, AFailedRunLeavesNoEmptyFolders) {
  // A DEM that fails as it builds the drum (a settled start whose source checkpoint is
  // there but unreadable): `run` created the output and cache folders and removes them again.
  const std::string dir = temp_dir("cli_empty");
  std::filesystem::remove_all(dir + "/out");
  std::filesystem::remove_all(dir + "/cache");
  std::filesystem::create_directories(dir + "/source");
  std::ofstream(dir + "/source/checkpoint.h5") << "not HDF5\n";
  std::ofstream(dir + "/case.yaml") << "dem:\n  drum: {diameter: 0.03, length: 0.04275, speed_rpm: 320.16}\n"
                                       "  initial_film: {from_run: source}\n"
                                       "  run: {duration: 0.01, dt: 2.0e-5}\n  sampling: {turns: 1}\n"
                                       "thermal: {grid: {nz: 10, nxi: 4}}\n";
  const BinaryRun r = run_binary({"run", dir + "/case.yaml", "--out", dir + "/out/a", "--cache", dir + "/cache", "--allow-small-drum"}, 60.0);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("dem.initial_film.from_run = source"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot resume from"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/cache")) << r.err;
}

TEST(CliUsage, DemFlagsOnACaseWithoutADemAreRefused) {
  // A thermal-only case runs no DEM: a seed (or any DEM flag) would be ignored without a word.
  const std::string dir = temp_dir("cli_dem_flags");
  for (const std::vector<std::string>& flag :
       {std::vector<std::string>{"--seed", "3"}, {"--threads", "2"}, {"--speed-rpm", "60"}}) {
    std::vector<std::string> args = {"run", CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml", "--out",
                                     dir + "/out", "--no-plots"};
    args.insert(args.end(), flag.begin(), flag.end());
    const BinaryRun r = run_binary(args, 60.0);
    EXPECT_NE(r.exit_code, 0) << flag[0] << ": " << r.err;
    EXPECT_NE(r.err.find("no DEM runs"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/summary.json")) << flag[0];
  }
  std::filesystem::remove_all(dir);
}

TEST(CliUsage, AFeedTheFeederCannotDeliverIsWarned) {
  // 0.3 kg/s is below the densest-packing bound the case check refuses above, but far more
  // than random insertion into the feeder region achieves: the run says so.
  const std::string dir = temp_dir("cli_feed");
  std::ofstream(dir + "/case.yaml") << "dem:\n  drum: {diameter: 0.03, length: 0.04275, speed_rpm: 320.16}\n"
                                       "  feeder: {mass_flow: 0.3}\n"
                                       "  run: {duration: 0.02, dt: 2.0e-5, threads: 1, checkpoint_interval: 0}\n";
  const BinaryRun r = run_binary({"dem", dir + "/case.yaml", "--out", dir + "/out"}, 60.0);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("WARNING: the feeder delivered"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("of the 300 g/s asked"), std::string::npos) << r.err;
  // summary.json carries the same warnings: the shortfall, a flow not steady after 0.02 s, and
  // the spin-up run past run.duration while it was not.
  std::ifstream in(dir + "/out/summary.json");
  const std::string summary((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* w : {"the feeder delivered", "the flow is not steady", "the spin-up ran"}) {
    EXPECT_NE(summary.find(w), std::string::npos) << w << " not in summary.json";
    EXPECT_NE(r.err.find(std::string("WARNING: ") + w), std::string::npos) << r.err;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliUsage, ASliceHasNoFeedOrOutletFlow) {
  // A periodic slice has no feeder and no outlet: its summary says null for those flows (a 0
  // read as a drum that carries nothing), and gives its own axial flow and target.
  const std::string dir = temp_dir("cli_slice");
  std::ofstream(dir + "/case.yaml")
      << "dem:\n  drum: {diameter: 0.03, length: 0.04275, speed_rpm: 320.16}\n"
         "  slice: {enabled: true, length_d: 4, target_mass_flow: 0.002}\n  initial_film: {particles: 300}\n"
         "  run: {duration: 0.02, max_extension: 0, dt: 2.0e-5, threads: 1, checkpoint_interval: 0}\n"
         "  sampling: {turns: 1, snapshots_per_turn: 2}\n";
  const BinaryRun r = run_binary({"dem", dir + "/case.yaml", "--out", dir + "/out", "--no-plots"}, 120.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = nlohmann::json::parse(std::ifstream(dir + "/out/summary.json"));
  std::printf("slice: target %s, inlet %s, outlet %s, slice flow %s of %s kg/s\n", s["target_mdot_kg_s"].dump().c_str(),
              s["inlet_mdot_kg_s"].dump().c_str(), s["outlet_mdot_kg_s"].dump().c_str(),
              s["slice_mdot_kg_s"].dump().c_str(), s["slice_target_mdot_kg_s"].dump().c_str());
  EXPECT_EQ(s["mode"], "slice");
  for (const char* key : {"target_mdot_kg_s", "inlet_mdot_kg_s", "outlet_mdot_kg_s"})
    EXPECT_TRUE(s[key].is_null()) << key << " = " << s[key];
  EXPECT_TRUE(s["slice_mdot_kg_s"].is_number());
  EXPECT_EQ(s["slice_target_mdot_kg_s"].get<double>(), 0.002);
  std::filesystem::remove_all(dir);
}

TEST(CliUsage, FlagsThatDoNotApplyAreRefused) {
  // Each was accepted and ignored without a word: DEM flags on a run without a DEM, a thermal
  // key on `dem`, figures asked for with --no-plots.
  const std::string dir = temp_dir("cli_not_apply");
  const std::string src = CENTREC_SOURCE_DIR;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"run", src + "/cases/thermal_centrec_uniform.yaml", "--out", dir + "/a", "--allow-unsteady"}, "--allow-unsteady"},
      {{"run", src + "/cases/thermal_centrec_uniform.yaml", "--out", dir + "/b", "--cache", dir + "/c"}, "--cache"},
      {{"dem", src + "/tests/coupling/small_coupled.yaml", "--out", dir + "/d", "--set", "thermal.T_in=900"},
       "thermal.T_in"},
      {{"run", src + "/cases/quickstart.yaml", "--out", dir + "/e", "--no-plots", "--figures", "pdf"}, "--figures"},
  };
  for (const auto& [args, expect] : cases) {
    const BinaryRun r = run_binary(args, 60.0);
    std::printf("%s %s: exit %d: %s", args[0].c_str(), expect.c_str(), r.exit_code, r.err.c_str());
    EXPECT_EQ(r.exit_code, 2) << expect;
    EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(args[3] + "/summary.json")) << expect;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliUsage, RunningOutOfMemoryIsAnErrorNotACrash) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
  // 1e8 particles fit this 1 m drum and pass every check, but need tens of GB; under a
  // 1 GB address-space limit (ulimit -v) the allocation fails. The run must end with one
  // clear line and exit 1: no std::bad_alloc text, no abort, no signal.
  const std::string dir = temp_dir("cli_memory");
  std::ofstream(dir + "/case.yaml") << "dem:\n  drum: {diameter: 1.0, length: 1.0, speed_rpm: 60}\n"
                                       "  initial_film: {particles: 100000000}\n"
                                       "  run: {duration: 0.01, threads: 1, checkpoint_interval: 0}\n";
  const BinaryRun v = run_binary({"validate", dir + "/case.yaml"}, 60.0);
  ASSERT_EQ(v.exit_code, 0) << "the case must pass the readers: " << v.err;
  const BinaryRun r = run_binary({"dem", dir + "/case.yaml", "--out", dir + "/out", "--no-plots"}, 120.0, 0.0, 1ull << 30);
  std::printf("stderr under a 1 GB limit:\n%s\n", r.err.c_str());
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("centrec dem: error: out of memory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out")) << "the output folder the failed run created is left behind";
  std::filesystem::remove_all(dir);
}

TEST(CliUsage, SetGivesAnyCaseKeyThroughItsOwnReader) {
  // --set KEY=VALUE writes the key into the case, which is read again: the key's own range
  // and spelling checks refuse a bad one, and the outputs hold the value that ran.
  const std::string dir = temp_dir("cli_set");
  const BinaryRun r = run_binary({"thermal", kThermal, "--out", dir + "/a", "--set", "thermal.T_in=900", "--set",
                                  "thermal.flux.q_film=3e5"},
                                 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("T_in 900.00 K"), std::string::npos) << r.out;
  std::ifstream summary(dir + "/a/summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"T_in_K\": 900.0"), std::string::npos) << text.substr(0, 300);
  EXPECT_NE(text.find("\"command_line_overrides\": \"--set thermal.T_in=900 --set thermal.flux.q_film=3e5\""),
            std::string::npos);
  expect_usage_error({"thermal", kThermal, "--out", dir + "/b", "--set", "thermal.T_inn=900"},
                     "unknown key 'thermal.T_inn' (did you mean 'T_in'?)");
  expect_usage_error({"thermal", kThermal, "--out", dir + "/b", "--set", "thermal.T_in=-900"},
                     "thermal.T_in = -900 is out of the allowed range");
  expect_usage_error({"thermal", kThermal, "--out", dir + "/b", "--set", "thermal.T_in"}, "is not KEY=VALUE");
  expect_usage_error({"thermal", kThermal, "--out", dir + "/b", "--set", "dem.seed=3"}, "has no `dem:` section");
  // `centrec dem --resume` continues the stored case: only the thread count may change.
  expect_usage_error({"dem", "--resume", dir + "/none", "--set", "dem.seed=3"}, "dem.seed cannot change a resumed run");
  EXPECT_FALSE(std::filesystem::exists(dir + "/b"));
  std::filesystem::remove_all(dir);
}
