// `centrec paths` end to end on a tiny fed drum (D/d 25, 0.2 s of spin-up and 6 sampled
// turns, ~10 s): dem writes the tracks, run maps and heats the drum's film (--dem-from), paths
// measures the residence times and heats the particles along their paths. The figures must
// hang together: the continuum film holds the DEM's mass, its mean residence is holdup /
// feed's, the particles' outlet temperatures lie between the inlet's and the film's hottest.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/reliability/run_binary.hpp"
#include "tests/test_case_dir.hpp"

using centrec::testing::run_binary;

TEST(PathsCli, ATinyFedDrumsResidenceTimesAndPathHeating) {
  const std::string dir = centrec::testing::fresh_dir("paths_cli");
  const std::string case_path = centrec::testing::write_case(dir, R"(title: tiny_fed_drum
dem:
  drum: {diameter: 0.03, length: 0.015, tilt_deg: 45, speed_rpm: 320.16}
  rough_wall: {enabled: true}
  feeder: {mass_flow: 4.0e-3, axial_length_d: 3}
  initial_film: {particles: 500}
  run: {duration: 0.2, dt: 2.0e-5, skin_d: 0.4, threads: 1}
  sampling: {turns: 6, snapshots_per_turn: 8, axial_sections: 5, tangential_bins: 12, bins: 8}
film: {mapping: along_drum}
thermal:
  model: 2d
  grid: {nz: 40, nxi: 20}
  T_in: 873.15
  flux: {profile: uniform, q_film: 2.0e5}
)");
  const auto dem = run_binary({"dem", case_path, "--out", dir + "/dem", "--no-plots"}, 300.0);
  ASSERT_EQ(dem.exit_code, 0) << dem.err;
  ASSERT_TRUE(std::filesystem::exists(dir + "/dem/tracks"));
  // The tiny drum is below the scale-down's size and not steady after 1 s: run is told so.
  const auto run = run_binary({"run", case_path, "--dem-from", dir + "/dem", "--out", dir + "/run", "--no-plots",
                               "--allow-unsteady", "--allow-small-drum"},
                              120.0);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto paths = run_binary(
      {"paths", case_path, "--dem", dir + "/dem", "--results", dir + "/run/results.h5", "--out", dir + "/paths"},
      120.0);
  ASSERT_EQ(paths.exit_code, 0) << paths.err;
  std::printf("%s", paths.out.c_str());
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(dir + "/paths/summary.json"));
  EXPECT_GT(s["complete_paths"].get<double>(), 500.0);
  EXPECT_GT(s["weighted_coverage"].get<double>(), 0.85);
  EXPECT_LT(s["weighted_coverage"].get<double>(), 1.02);
  EXPECT_NEAR(s["film_mass_over_dem_mass"].get<double>(), 1.0, 0.05);
  EXPECT_NEAR(s["mean_residence_film_implies_drum_s"].get<double>() / s["mean_residence_little_s"].get<double>(), 1.0,
              0.1);
  const auto& T = s["T_out_paths_K"];
  EXPECT_GE(T["q05"].get<double>(), 873.15 - 1e-9);
  EXPECT_LE(T["q05"].get<double>(), T["q50"].get<double>());
  EXPECT_LE(T["q50"].get<double>(), T["q95"].get<double>());
  EXPECT_LE(T["max"].get<double>(), s["T_surface_max_K"].get<double>() + 50.0);
  EXPECT_TRUE(std::filesystem::exists(dir + "/paths/paths.csv"));
  // A DEM folder without tracks (a slice's, or none) is refused with the reason.
  std::filesystem::remove_all(dir + "/dem/tracks");
  const auto none = run_binary(
      {"paths", case_path, "--dem", dir + "/dem", "--results", dir + "/run/results.h5", "--out", dir + "/paths2"},
      60.0);
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.err.find("tracks"), std::string::npos) << none.err;
  std::filesystem::remove_all(dir);
}
