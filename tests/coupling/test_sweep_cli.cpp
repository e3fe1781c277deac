// `centrec sweep`: the small coupled case over 1 speed x 2 mass flows as two
// parallel `centrec run` processes; the table has one row per point with its outlet
// temperature and k_eff, the points differ, and a sweep of a case without a DEM is refused.
#include <gtest/gtest.h>

#include "tests/test_case_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "runs/headline_figures.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kCase = std::string(CENTREC_SOURCE_DIR) + "/tests/coupling/small_coupled.yaml";

}  // namespace

TEST(SweepCli, TwoPointsInParallelGiveATable) {
  const std::string dir = centrec::testing::temp_dir("sweep");
  std::ifstream in(kCase);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += "sweep: {speed_rpm: [160.08], mass_flow: [0.0357, 0.03], parallel: 2}\n";
  std::ofstream(dir + "/case.yaml") << text;
  // Below the validity threshold the sweep is refused before any point starts.
  const std::string base = std::string(CENTREC_BINARY) + " sweep " + dir + "/case.yaml --out " + dir + "/sweep";
  EXPECT_NE(std::system((base + " > " + dir + "/refused 2>&1").c_str()), 0);
  std::ifstream refused(dir + "/refused");
  const std::string why((std::istreambuf_iterator<char>(refused)), std::istreambuf_iterator<char>());
  std::printf("%s", why.c_str());
  EXPECT_NE(why.find("validity threshold"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/sweep/rpm160.08_mdot0.0357"));
  const std::string cmd = base + " --allow-small-drum > " + dir + "/log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir + "/log");
  std::string out((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  std::printf("%s\n", out.substr(out.find("centrec sweep")).c_str());
  ASSERT_EQ(rc, 0);
  std::ifstream js(dir + "/sweep/sweep.json");
  const auto j = nlohmann::json::parse(js);
  ASSERT_EQ(j["points"].size(), 2u);
  const auto& a = j["points"][0];
  const auto& b = j["points"][1];
  EXPECT_EQ(a["status"], 0);
  EXPECT_EQ(b["status"], 0);
  // Every point says whether its DEM was steady (this short run is not) and what was allowed.
  for (const auto* p : {&a, &b}) {
    const std::string flow = (*p)["dem_flow"];
    EXPECT_NE(flow.find((*p)["dem_flow_steady"].get<bool>() ? ": steady" : "NOT steady"), std::string::npos) << flow;
    EXPECT_FALSE((*p)["warnings"].empty());
  }
  EXPECT_GT(a["T_out_K"].get<double>(), 873.15);
  EXPECT_GT(a["k_eff_W_mK"].get<double>(), 0.0);
  // Different feeds, different DEM films, different answers.
  EXPECT_NE(a["T_out_K"].get<double>(), b["T_out_K"].get<double>());
  // sweep.csv and sweep.json carry every headline figure (runs/headline_figures.hpp) under its
  // column, each the number in the point's own summary.json.
  std::ifstream csv(dir + "/sweep/sweep.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  std::vector<std::string> columns, cells;
  for (auto* v : {&columns, &cells}) {
    std::stringstream line(v == &columns ? header : first);
    for (std::string c; std::getline(line, c, ',');) v->push_back(c);
  }
  const auto point = nlohmann::json::parse(std::ifstream(a["dir"].get<std::string>() + "/summary.json"));
  ASSERT_EQ(columns.size(), cells.size()) << header << "\n" << first;
  for (const auto& f : centrec::runs::headline_figures()) {
    const auto at = std::find(columns.begin(), columns.end(), f.column);
    ASSERT_NE(at, columns.end()) << f.column << " missing from " << header;
    double v = 0.0;
    ASSERT_TRUE(centrec::runs::headline_value(point, f, v)) << f.pointer;
    EXPECT_NEAR(std::stod(cells[at - columns.begin()]), v, 1e-5 * std::abs(v)) << f.column;  // csv: 6 digits
    EXPECT_EQ(a[f.column].get<double>(), v) << f.column;
  }
  fs::remove_all(dir);
}

// A study over any case key: --grid twice gives the Cartesian product; the points that share
// their DEM (a thermal-only change) run it once; sweep.csv has the swept keys and the inputs
// that define each point as plain columns, each equal to what the point ran with.
TEST(SweepCli, GridOverThermalKeysSharesOneDem) {
  const std::string dir = centrec::testing::temp_dir("sweep_grid");
  const std::string cmd = std::string(CENTREC_BINARY) + " sweep " + kCase + " --out " + dir +
                          "/study --allow-small-drum --grid thermal.flux.q_film=1.5e5,2e5 --grid thermal.T_in=800,873.15"
                          " --figures png,pdf --dpi 80 > " + dir + "/log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir + "/log");
  const std::string out((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  std::printf("%s\n", out.c_str());
  ASSERT_EQ(rc, 0);
  const auto j = nlohmann::json::parse(std::ifstream(dir + "/study/sweep.json"));
  ASSERT_EQ(j["axes"].size(), 2u);
  EXPECT_EQ(j["axes"][0]["key"], "thermal.flux.q_film");
  ASSERT_EQ(j["points"].size(), 4u);
  int dem_runs = 0;
  std::map<std::pair<double, double>, double> t_out;
  for (const auto& p : j["points"]) {
    ASSERT_EQ(p["status"], 0);
    const auto s = nlohmann::json::parse(std::ifstream(p["dir"].get<std::string>() + "/summary.json"));
    dem_runs += s["dem"]["cached"].get<bool>() ? 0 : 1;
    const double q = p["thermal.flux.q_film"], t_in = p["thermal.T_in"];
    // The plain inputs are what the point ran with: its T_in, its flux (uniform: the mean).
    EXPECT_EQ(s["point"]["T_in_K"].get<double>(), t_in);
    EXPECT_EQ(p["T_in_K"].get<double>(), t_in);
    EXPECT_NEAR(p["flux_film_mean_W_m2"].get<double>(), q, 1e-9 * q);
    EXPECT_EQ(p["seed"].get<double>(), 12345);
    EXPECT_EQ(p["dt_s"].get<double>(), 2e-5);
    EXPECT_EQ(p["speed_rpm"].get<double>(), 160.08);
    t_out[{q, t_in}] = p["T_out_K"];
  }
  EXPECT_EQ(dem_runs, 1) << "four points of one DEM ran it " << dem_runs << " times";
  // More flux, hotter outlet; a hotter inlet, a hotter outlet.
  const double hot = t_out[{2e5, 800}], cool = t_out[{1.5e5, 800}], hot_in = t_out[{2e5, 873.15}];
  EXPECT_GT(hot, cool);
  EXPECT_GT(hot_in, hot);
  std::ifstream csv(dir + "/study/sweep.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("thermal.flux.q_film,thermal.T_in,speed_rpm,mass_flow_kg_s,T_in_K,flux_film_mean_W_m2,seed,dt_s,", 0),
            0u) << header;
  // --figures png,pdf --dpi 80: each chart in both formats, the PNG 11 in x 80 dpi wide.
  EXPECT_TRUE(fs::exists(dir + "/study/sweep_map.pdf"));
  std::ifstream png(dir + "/study/sweep_map.png", std::ios::binary);
  unsigned char head[24] = {};
  png.read(reinterpret_cast<char*>(head), sizeof head);
  const unsigned width = (head[16] << 24) | (head[17] << 16) | (head[18] << 8) | head[19];
  EXPECT_EQ(width, 880u) << "sweep_map.png is not 11 in at 80 dpi";
  fs::remove_all(dir);
}

// The points are checked before any starts: a value the key's reader refuses, a repeated
// point (2e5 and 200000 are one value), a key swept and set, a CSV row of the wrong width.
TEST(SweepCli, RefusesBadPointsBeforeAnyRuns) {
  const std::string dir = centrec::testing::temp_dir("sweep_refusals");
  std::ofstream(dir + "/bad.csv") << "thermal.T_in,thermal.flux.q_film\n800,2e5\n900\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--grid thermal.T_in=800,5000", "thermal.T_in"},
      {"--grid thermal.flux.q_film=2e5,200000", "given twice"},
      {"--grid thermal.T_in=800,900 --set thermal.T_in=850", "both swept and set"},
      {"--grid thermal.nonsense=1,2", "nonsense"},
      {"--grid speed_rpm=-3,160", "speed_rpm"},
      {"--points " + dir + "/bad.csv", "bad.csv:3"},
  };
  for (const auto& [flags, expect] : cases) {
    const std::string out = dir + "/out";
    const std::string cmd = std::string(CENTREC_BINARY) + " sweep " + kCase + " --allow-small-drum --out " + out +
                            " " + flags + " > " + dir + "/log 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream log(dir + "/log");
    const std::string why((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    std::printf("%s -> %s", flags.c_str(), why.c_str());
    EXPECT_NE(rc, 0) << flags;
    EXPECT_NE(why.find(expect), std::string::npos) << flags << ": " << why;
    EXPECT_FALSE(fs::exists(out)) << flags << ": a folder was made before the points were checked";
  }
  fs::remove_all(dir);
}

// A key that `centrec dem` sets by a flag of its own (--duration, --wall-rolling-model) reaches
// each point's `centrec run`, which has no such flag, as --set: the points run.
TEST(SweepCli, DemOnlyFlagKeysReachThePointsAsSet) {
  const std::string dir = centrec::testing::temp_dir("sweep_dem_keys");
  const std::string cmd = std::string(CENTREC_BINARY) + " sweep " + kCase + " --out " + dir +
                          "/s --allow-small-drum --no-plots --parallel 1 --set dem.run.duration=0.1"
                          " --grid thermal.T_in=800,873.15 > " + dir + "/log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir + "/log");
  const std::string out((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  std::ifstream point_log(dir + "/s/T_in800/run.log");
  const std::string point((std::istreambuf_iterator<char>(point_log)), std::istreambuf_iterator<char>());
  EXPECT_EQ(rc, 0) << out << "\n" << point;
  const auto s = nlohmann::json::parse(std::ifstream(dir + "/s/T_in800/summary.json"));
  EXPECT_NE(s["resolved_config"].get<std::string>().find("duration: 0.1"), std::string::npos);
  fs::remove_all(dir);
}

// A case whose film is given (no DEM) sweeps too: its points get no DEM flags.
TEST(SweepCli, AFilmWithoutADemSweeps) {
  const std::string dir = centrec::testing::temp_dir("sweep_thermal_only");
  const std::string cmd = std::string(CENTREC_BINARY) + " sweep " + CENTREC_SOURCE_DIR +
                          "/cases/thermal_centrec_uniform.yaml --out " + dir +
                          "/s --no-plots --grid thermal.T_in=800,900 > " + dir + "/log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir + "/log");
  const std::string out((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  std::printf("%s\n", out.c_str());
  ASSERT_EQ(rc, 0) << out;
  const auto j = nlohmann::json::parse(std::ifstream(dir + "/s/sweep.json"));
  ASSERT_EQ(j["points"].size(), 2u);
  EXPECT_LT(j["points"][0]["T_out_K"].get<double>(), j["points"][1]["T_out_K"].get<double>());
  EXPECT_EQ(j["points"][0]["T_in_K"].get<double>(), 800.0);
  EXPECT_TRUE(j["points"][0]["seed"].is_null() || !j["points"][0].contains("seed"));
  fs::remove_all(dir);
}
