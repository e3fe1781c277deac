// `centrec export-liggghts` writes the drum `centrec dem` and `centrec run` simulate: for a
// case whose receiver derives the DEM drum (receiver.dem_diameter_d, eqs 1-3), the deck's
// drum, speed, glued rough-wall spheres, starting film and flow are the native scene's,
// built here from the case by the configuration library (not by the command).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../reliability/run_binary.hpp"
#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "dem/scene/centrec_scene.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(LiggghtsExportCli, QuickstartDeckIsTheNativeScene) {
  const std::string case_path = std::string(CENTREC_SOURCE_DIR) + "/cases/quickstart.yaml";
  const fs::path dir = fs::temp_directory_path() / ("centrec_export_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto r = centrec::testing::run_binary(
      {"export-liggghts", case_path, "--out", dir.string(), "--wall-rolling-model", "liggghts"}, 120.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // The native scene of the same case (the rolling model does not change the build).
  const centrec::config::CaseFile cf = centrec::config::read_case_file(case_path);
  ASSERT_TRUE(cf.receiver && cf.dem);
  const centrec::config::DemCase dc = centrec::config::effective_dem(*cf.dem, &*cf.receiver, {});
  centrec::dem::scene::SceneConfig sc = dc.scene;
  sc.threads = 1;
  const centrec::dem::scene::CentrecScene native(sc);

  const std::string deck = slurp(dir / "in.centrec");
  double D = 0, L = 0, omega = 0;
  const std::size_t h = deck.find("# D = ");
  ASSERT_NE(h, std::string::npos);
  ASSERT_EQ(std::sscanf(deck.c_str() + h, "# D = %lf m, L = %lf m, omega = %lf rad/s", &D, &L, &omega), 3);
  long long glued = -1, atoms = -1;
  const std::size_t g = deck.find("group glued id <= ");
  ASSERT_NE(g, std::string::npos);
  ASSERT_EQ(std::sscanf(deck.c_str() + g, "group glued id <= %lld", &glued), 1);
  const std::string data = slurp(dir / "data.centrec");
  const std::size_t a = data.find(" atoms");
  ASSERT_NE(a, std::string::npos);
  atoms = std::stoll(data.substr(data.rfind('\n', a) + 1, a - data.rfind('\n', a) - 1));
  std::printf("deck: D %.6g m, L %.6g m, omega %.9g rad/s, %lld glued, %lld atoms\n", D, L, omega, glued, atoms);
  std::printf("native: D %.6g m, L %.6g m, omega %.9g rad/s, %lld glued, %lld free\n", sc.drum.diameter,
              sc.slice.length, sc.drum.omega, static_cast<long long>(native.glued_particles()),
              static_cast<long long>(native.free_particles()));
  // The derived drum (D/d 80 of the 0.12 m receiver), not the receiver's own.
  EXPECT_NEAR(D, 80 * sc.particle.diameter, 1e-9);
  EXPECT_NEAR(D, sc.drum.diameter, 1e-9 * sc.drum.diameter);
  EXPECT_NEAR(L, sc.slice.length, 1e-9 * sc.slice.length);
  EXPECT_NEAR(omega, sc.drum.omega, 1e-8 * sc.drum.omega);
  EXPECT_EQ(glued, native.glued_particles());
  EXPECT_EQ(atoms, native.glued_particles() + native.free_particles());
  // The flow: the slice's target, named in the command's summary line and, as a difference
  // from the native engine (no controller in the deck), in the deck.
  char target[64];
  std::snprintf(target, sizeof target, "slice target %.4g g/s", 1e3 * sc.slice.target_mass_flow);
  EXPECT_NE(r.out.find(target), std::string::npos) << r.out;
  EXPECT_NE(deck.find("# Differs from the native engine: the slice's holdup controller"), std::string::npos);
  // `validate` names the same drum.
  const auto v = centrec::testing::run_binary({"validate", case_path}, 60.0);
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::size_t vl = v.out.find("# DEM drum (derived from the receiver");
  ASSERT_NE(vl, std::string::npos) << v.out.substr(0, 300);
  double vD = 0;
  ASSERT_EQ(std::sscanf(v.out.c_str() + v.out.find("D = ", vl), "D = %lf m", &vD), 1);
  EXPECT_NEAR(vD, sc.drum.diameter, 1e-4 * sc.drum.diameter);
  EXPECT_NE(v.out.find(target, vl), std::string::npos) << v.out.substr(vl, 300);
  fs::remove_all(dir);
}
