// The LIGGGHTS export: a golden deck for a small case, so any
// change to the export is a visible diff, the files it writes, and the refusal of
// settings LIGGGHTS cannot express.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/case_file.hpp"
#include "liggghts/liggghts_export.hpp"
#include "liggghts/liggghts_materials.hpp"
#include "liggghts/liggghts_stl.hpp"

using namespace centrec::config;
using namespace centrec::liggghts;
namespace fs = std::filesystem;

namespace {

const std::string kCase = std::string(CENTREC_SOURCE_DIR) + "/tests/liggghts/small_drum.yaml";
const std::string kGolden = std::string(CENTREC_SOURCE_DIR) + "/tests/liggghts/golden/in.centrec";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The deck without its "written by ... (centrec VERSION)" line, which names the commit.
std::string without_version(const std::string& deck) {
  std::istringstream in(deck);
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("# written by", 0) != 0) out += line + "\n";
  return out;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t k = text.find(what); k != std::string::npos; k = text.find(what, k + 1)) ++n;
  return n;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("centrec_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

CaseFile small_case() {
  CaseFile cf = read_case_file(kCase);
  cf.path = "tests/liggghts/small_drum.yaml";  // the deck names the case; keep it machine-independent
  return cf;
}

}  // namespace

TEST(LiggghtsExport, DeckMatchesGolden) {
  const CaseFile cf = small_case();
  const fs::path dir = fresh_dir("golden");
  export_liggghts(cf, *cf.dem, dir.string());
  const std::string deck = without_version(slurp((dir / "in.centrec").string()));
  if (std::getenv("CENTREC_UPDATE_GOLDEN")) {
    std::ofstream(kGolden) << deck;
    GTEST_SKIP() << "golden deck rewritten: " << kGolden;
  }
  const std::string golden = slurp(kGolden);
  ASSERT_FALSE(golden.empty()) << "missing " << kGolden << " (CENTREC_UPDATE_GOLDEN=1 writes it)";
  EXPECT_EQ(deck, golden) << "the exported deck changed; if intended, rerun with CENTREC_UPDATE_GOLDEN=1 and "
                             "review the diff of "
                          << kGolden;
  fs::remove_all(dir);
}

TEST(LiggghtsExport, WritesDataAndGeometryOfTheScene) {
  const CaseFile cf = small_case();
  const fs::path dir = fresh_dir("files");
  const LiggghtsDeckPlan plan = export_liggghts(cf, *cf.dem, dir.string());
  // The data file holds the native scene's glued layer and starting film, ids in order.
  const std::string data = slurp((dir / plan.data).string());
  EXPECT_EQ(plan.initial_free, 200);
  EXPECT_GT(plan.glued, 0);
  EXPECT_NE(data.find(std::to_string(plan.glued + plan.initial_free) + " atoms"), std::string::npos);
  // Cylinder STL (two triangles per facet) and the ends' STL: back plate (a fan: one
  // triangle per sector) + lip (two per sector), same sectors as the cylinder's columns.
  ASSERT_TRUE(plan.has_ends);
  const std::string cylinder = slurp((dir / plan.drum_stl).string());
  const std::string ends = slurp((dir / plan.ends_stl).string());
  const std::string outlet = slurp((dir / plan.outlet_stl).string());
  const int sectors = count(outlet, "endfacet");  // the outlet face is a fan: one per sector
  EXPECT_GE(sectors, 24);
  EXPECT_EQ(sectors, plan.drum_facets_around);
  EXPECT_EQ(count(cylinder, "endfacet"), 2 * plan.drum_facets_around * plan.drum_facets_axial);
  EXPECT_EQ(count(ends, "endfacet"), 3 * sectors);
  // History crosses facet columns: curvature above their turn, below the triangles' smallest angle.
  const double R = 0.015, lip = 0.0012, L = 0.012;
  const double turn = 360.0 / plan.drum_facets_around;
  const double width = 2.0 * R * std::sin(M_PI / plan.drum_facets_around), height = L / plan.drum_facets_axial;
  const double smallest = std::atan(std::min(width, height) / std::max(width, height)) * 180.0 / M_PI;
  std::printf("facet columns turn %.3f deg, curvature %.3f deg, smallest triangle angle %.3f deg\n", turn,
              plan.drum_curvature_deg, smallest);
  EXPECT_GT(plan.drum_curvature_deg, turn);
  EXPECT_LT(plan.drum_curvature_deg, smallest);
  const std::string drum = cylinder + ends;
  // Every vertex lies on the analytic geometry: radius R (cylinder, plate rim, lip rim),
  // R - lip (lip inner rim) or the axis (plate centre).
  std::istringstream in(drum);
  std::string word;
  double worst = 0.0;
  while (in >> word) {
    if (word != "vertex") continue;
    double x, y, z;
    in >> x >> y >> z;
    const double r = std::hypot(x, y);
    const double e = std::min({std::fabs(r - R), std::fabs(r - (R - lip)), r});
    worst = std::max(worst, e);
    EXPECT_TRUE(z > -1e-12 && z < L + 1e-12) << z;
  }
  std::printf("largest vertex distance from the analytic drum: %.3g m (tolerance 1e-12)\n", worst);
  EXPECT_LT(worst, 1e-12);
  // Dumps every turn / snapshots_per_turn: 640 rpm, 4 per turn, dt 2e-5 -> round(1171.875).
  EXPECT_EQ(plan.dump_every, 1172);
  EXPECT_EQ(plan.spinup_steps % plan.dump_every, 0);
  EXPECT_EQ(plan.sampling_steps, 4 * plan.dump_every);
  fs::remove_all(dir);
}

// The static drum mesh (the wall moves only by its surface velocity) is a polygon a
// particle held on the wall rides over: its sagitta must stay near the Hertz overlap of a
// wall-layer particle (~1e-3 d), not 10 times it, or the stuck layer is shaken loose.
TEST(LiggghtsExport, DrumMeshWithinAThousandthOfADiameter) {
  const CaseFile cf = small_case();
  const fs::path dir = fresh_dir("sagitta");
  const LiggghtsDeckPlan plan = export_liggghts(cf, *cf.dem, dir.string());
  const double R = 0.5 * cf.dem->scene.drum.diameter, d = cf.dem->scene.particle.diameter;
  const double sagitta = R * (1.0 - std::cos(M_PI / plan.drum_facets_around));
  std::printf("%d facet columns: sagitta %.3g m = %.2e d (limit 1e-3 d)\n", plan.drum_facets_around, sagitta,
              sagitta / d);
  EXPECT_LE(sagitta, 1e-3 * d);
  fs::remove_all(dir);
}

// A rolling model LIGGGHTS 3.8 lacks (dem/rolling_models.hpp, RollingModelInfo::liggghts
// nullptr: sds) is refused with its key and name, before any file is written.
TEST(LiggghtsExport, RefusesARollingModelLiggghtsLacksByName) {
  CaseFile cf = small_case();
  DemCase dc = *cf.dem;
  dc.scene.particle_wall.rolling_model = centrec::dem::RollingModel::sds;
  dc.scene.particle_wall.rolling_coefficients = centrec::dem::default_rolling_coefficients(centrec::dem::RollingModel::sds);
  const fs::path dir = fresh_dir("refuse_sds");
  try {
    export_liggghts(cf, dc, dir.string());
    FAIL() << "the sds rolling model was exported";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contacts.particle_wall.rolling_model: sds - LIGGGHTS 3.8 has no sds"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "in.centrec"));
  centrec::liggghts::LiggghtsMaterials m;
  m.particle_particle = dc.scene.particle_wall;
  EXPECT_THROW(centrec::liggghts::liggghts_material_commands(m), std::invalid_argument);
}

TEST(LiggghtsExport, RefusesTheRelativeWallRollingModelByName) {
  CaseFile cf = small_case();
  DemCase dc = *cf.dem;
  dc.scene.wall_rolling = centrec::dem::WallRolling::relative;
  const fs::path dir = fresh_dir("refuse");
  try {
    export_liggghts(cf, dc, dir.string());
    FAIL() << "the relative wall rolling model was exported";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contacts.wall_rolling_model: relative"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "in.centrec"));
  dc.scene.drum.omega = 0.0;
  const auto why = liggghts_inexpressible(dc);
  ASSERT_EQ(why.size(), 2u);
  EXPECT_NE(why[1].find("drum.speed_rpm"), std::string::npos) << why[1];
}

// The curvature that carries contact history across facet columns exists only while the
// triangles are less slender than the turn between columns.
TEST(LiggghtsExport, CylinderCurvatureBetweenColumnTurnAndSmallestAngle) {
  // 79 columns on R = 15 mm, 1.19 mm wide, 10 times as long: turn 4.56 deg, smallest angle 5.71 deg.
  const double R = 0.015, width = 2.0 * R * std::sin(M_PI / 79);
  const double c = cylinder_curvature_deg(R, 10 * width, 79, 1);
  std::printf("curvature %.4f deg (turn %.4f, smallest angle %.4f)\n", c, 360.0 / 79, std::atan(0.1) * 180 / M_PI);
  EXPECT_NEAR(c, 0.5 * (360.0 / 79 + std::atan(0.1) * 180 / M_PI), 1e-12);
  // 40 times as long: smallest angle 1.43 deg < turn 4.56 deg -> refused with the reason.
  EXPECT_THROW(cylinder_curvature_deg(R, 40 * width, 79, 1), std::invalid_argument);
}
