// Golden thermal cases: cases/thermal_*.yaml reproduce their stored outlet
// temperatures within 0.1 K. The stored values were recorded when the cases were added; a
// change beyond 0.1 K means the model or the numerics changed and must be explained. The
// cases that do not name their advection scheme take the default, van Leer (second order),
// since that became the default (docs/thermal_model.md, "Discretisation").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "config/case_thermal.hpp"
#include "runs/thermal_case_run.hpp"

using namespace centrec::config;
using namespace centrec::runs;

namespace {
struct Golden {
  const char* file;
  double T_out;      // steady outlet mixing-cup temperature, K
  double T_out_end;  // transient end value, K (0 if no transient)
};
const Golden kGolden[] = {
    {"thermal_centrec_uniform.yaml", 1375.4948955193504, 0.0},
    {"thermal_centrec_gaussian_1d.yaml", 1335.9428529708077, 0.0},
    {"thermal_centrec_gaussian_2d.yaml", 1324.8022982645136, 0.0},
    {"thermal_cloud_transient.yaml", 1375.6789501798428, 1706.2107997704243},
    {"thermal_centrec_cavity.yaml", 1472.319582180427, 0.0},  // the cavity model
};
}  // namespace

TEST(ThermalGoldenCases, OutletTemperaturesWithin0p1K) {
  for (const Golden& g : kGolden) {
    const ThermalCase c = read_thermal_case(std::string(CENTREC_SOURCE_DIR) + "/cases/" + g.file);
    const ThermalRun r = run_thermal_case(c);
    std::printf("%s: T_out %.4f K, stored %.4f K, |diff| %.2e K (tolerance 0.1 K)\n", g.file, r.balance.T_out, g.T_out,
                std::abs(r.balance.T_out - g.T_out));
    EXPECT_NEAR(r.balance.T_out, g.T_out, 0.1) << g.file;
    if (g.T_out_end > 0) {
      ASSERT_TRUE(r.has_transient);
      const double end = r.transient.samples.back().balance.T_out;
      std::printf("  transient end: T_out %.4f K, stored %.4f K, |diff| %.2e K (tolerance 0.1 K)\n", end, g.T_out_end,
                  std::abs(end - g.T_out_end));
      EXPECT_NEAR(end, g.T_out_end, 0.1) << g.file;
    }
  }
}

// The coupled case's defaults follow the evidence of docs/slice_vs_drum_thermal.md and
// docs/coupling.md: the sunlight by each cell's own phi (the form the ray-trace test supports,
// and the one the two-flux top accepts), the DEM's film up to where it carries 99.5 % of its
// flow (the edge that closes the flux for every seed and time step measured).
#include "config/case_file.hpp"
TEST(ThermalCases, CoupledDefaultsAreLocalExtinctionAndTheCarriedFlowEdge) {
  const centrec::config::CaseFile cf = centrec::config::read_case_file(CENTREC_SOURCE_DIR "/cases/quickstart.yaml");
  ASSERT_TRUE(cf.thermal);
  EXPECT_TRUE(cf.thermal->model.surface.extinction_local);
  EXPECT_LT(cf.thermal->model.surface.extinction_depth_d, 0.0);
  EXPECT_TRUE(centrec::thermal::solar_by_local_phi(cf.thermal->model.surface));
  EXPECT_EQ(cf.thermal->film_source.mapping, "as_measured_carried_flow");
}
