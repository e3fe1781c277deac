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
