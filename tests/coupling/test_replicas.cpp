// `centrec run --replicas N`: the spread of the coupled answer over DEM seeds.
// Unit: mean and sample standard deviation against hand values; the combined summary
// carries both and the means at the top level. End to end: the small coupled case with two
// seeds gives two different DEM films (different cache entries, different T_out), and the
// reported mean and std are those of the two replicas' own summaries.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

#include "runs/replica_summary.hpp"
#include "tests/test_case_dir.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kCase = std::string(CENTREC_SOURCE_DIR) + "/tests/coupling/small_coupled.yaml";

nlohmann::json fake_summary(double t_out, double eff, double k, bool steady) {
  return {{"T_out_K", t_out},
          {"efficiency", eff},
          {"mass_flow_kg_s", 0.0357},
          {"k_eff", {{"film_mean", {{"k_eff", k}, {"bed_conduction", 0.2}, {"radiation", 0.3}, {"mixing", k - 0.5}}}}},
          {"film", {{"mean_thickness_d", 4.0}}},
          {"coupling", {{"flow_closure_mean", 1.01}, {"imposed_velocity_factor", 1.1}}},
          {"dem", {{"steady", steady}, {"measured_mdot_kg_s", 0.03}}},
          {"warnings", steady ? nlohmann::json::array() : nlohmann::json::array({"not steady"})}};
}

// `centrec run --replicas n` of the small coupled case into dir/run, its output (printed) in `out`.
int run_replicas(const std::string& dir, int n, std::string& out) {
  const std::string cmd = std::string(CENTREC_BINARY) + " run " + kCase + " --out " + dir + "/run --replicas " +
                          std::to_string(n) + " --threads 2 --no-plots --allow-small-drum --allow-unsteady > " + dir +
                          "/log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir + "/log");
  out.assign(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>());
  std::printf("%s\n", out.c_str());
  return rc;
}
}  // namespace

TEST(Replicas, SpreadIsTheSampleStandardDeviation) {
  // 1, 2, 3, 4: mean 2.5, sample variance (2.25 + 0.25 + 0.25 + 2.25) / 3 = 5/3.
  const auto s = centrec::runs::spread({1.0, 2.0, 3.0, 4.0});
  std::printf("mean %.6f std %.6f (expected 2.5, %.6f)\n", s.mean, s.std, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.std, std::sqrt(5.0 / 3.0), 1e-15);
  EXPECT_EQ(centrec::runs::spread({7.0}).std, 0.0);
}

TEST(Replicas, CombinedSummaryHoldsMeansAndSpread) {
  const auto c =
      centrec::runs::combine_replicas({fake_summary(1100.0, 0.90, 0.9, true), fake_summary(1110.0, 0.92, 1.0, false),
                                       fake_summary(1120.0, 0.94, 1.1, true)},
                                      {5, 6, 7}, {"a", "b", "c"});
  EXPECT_DOUBLE_EQ(c["T_out_K"].get<double>(), 1110.0);
  EXPECT_NEAR(c["efficiency"].get<double>(), 0.92, 1e-15);
  EXPECT_NEAR(c["k_eff"]["film_mean"]["k_eff"].get<double>(), 1.0, 1e-15);
  const auto& f = c["replicas"]["figures"]["/T_out_K"];
  EXPECT_DOUBLE_EQ(f["std"].get<double>(), 10.0);
  EXPECT_EQ(f["values"].size(), 3u);
  EXPECT_EQ(c["replicas"]["seeds"][2].get<int>(), 7);
  // One unsteady replica makes the combined run unsteady and its warning is kept.
  EXPECT_FALSE(c["dem"]["steady"].get<bool>());
  EXPECT_EQ(c["warnings"].size(), 1u);
  nlohmann::json broken = fake_summary(1.0, 1.0, 1.0, true);
  broken.erase("T_out_K");
  EXPECT_THROW(centrec::runs::combine_replicas({broken}, {1}, {"x"}), std::invalid_argument);
}

TEST(Replicas, TwoSeedsOfTheSmallCoupledCase) {
  const std::string dir = centrec::testing::temp_dir("replicas");
  std::string out;
  const int rc = run_replicas(dir, 2, out);
  ASSERT_EQ(rc, 0);
  std::ifstream js(dir + "/run/summary.json");
  const auto s = nlohmann::json::parse(js);
  std::ifstream j0(dir + "/run/replica_0/summary.json"), j1(dir + "/run/replica_1/summary.json");
  const auto r0 = nlohmann::json::parse(j0), r1 = nlohmann::json::parse(j1);
  const double t0 = r0["T_out_K"].get<double>(), t1 = r1["T_out_K"].get<double>();
  // Seeds 12345 and 12346: two DEM runs (two cache entries), two films, two answers.
  EXPECT_NE(r0["dem"]["cache_key"], r1["dem"]["cache_key"]);
  EXPECT_NE(t0, t1);
  const auto& f = s["replicas"]["figures"]["/T_out_K"];
  EXPECT_NEAR(f["mean"].get<double>(), 0.5 * (t0 + t1), 1e-9);
  EXPECT_NEAR(f["std"].get<double>(), std::abs(t0 - t1) / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s["T_out_K"].get<double>(), 0.5 * (t0 + t1), 1e-9);
  EXPECT_EQ(s["replicas"]["seeds"][1].get<int>(), 12346);
  EXPECT_NE(out.find("T_out_K"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Replicas, AFailedReplicaIsNamedAndTheSpreadIsOverTheOthers) {
  // Three seeds; the second replica's folder is held by this (live) process's run lock, so
  // that replica is refused: the summary is the spread of seeds 12345 and 12347, names seed
  // 12346 with the child's reason, and the command still exits non-zero.
  const std::string dir = centrec::testing::temp_dir("replicas_failed");
  fs::create_directories(dir + "/run/replica_1");
  std::ofstream(dir + "/run/replica_1/.centrec-run.lock") << "pid " << ::getpid() << "\ncommand centrec run held.yaml\n";
  std::string out;
  const int rc = run_replicas(dir, 3, out);
  EXPECT_NE(rc, 0);
  ASSERT_TRUE(fs::exists(dir + "/run/summary.json"));
  std::ifstream js(dir + "/run/summary.json");
  const auto s = nlohmann::json::parse(js);
  std::ifstream j0(dir + "/run/replica_0/summary.json"), j2(dir + "/run/replica_2/summary.json");
  const auto r0 = nlohmann::json::parse(j0), r2 = nlohmann::json::parse(j2);
  const double t0 = r0["T_out_K"].get<double>(), t2 = r2["T_out_K"].get<double>();
  EXPECT_NEAR(s["replicas"]["figures"]["/T_out_K"]["mean"].get<double>(), 0.5 * (t0 + t2), 1e-9);
  EXPECT_EQ(s["replicas"]["seeds"].size(), 2u);
  EXPECT_EQ(s["replicas"]["seeds"][1].get<int>(), 12347);
  ASSERT_EQ(s["replicas"]["failed"].size(), 1u);
  const auto& f = s["replicas"]["failed"][0];
  std::printf("failed: %s\n", f.dump().c_str());
  EXPECT_EQ(f["seed"].get<int>(), 12346);
  EXPECT_NE(f["reason"].get<std::string>().find("in use by another centrec run"), std::string::npos);
  bool warned = false;
  for (const auto& w : s["warnings"]) warned = warned || w.get<std::string>().find("seed 12346 failed") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_NE(out.find("over 2 DEM seeds of 3"), std::string::npos);
  fs::remove_all(dir);
}
