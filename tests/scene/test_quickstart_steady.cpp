// Slow: the README's quickstart drum reaches the cold steady state, i.e. its outlet
// mass flow converges to the inlet mass flow. Runs the case file itself.
#include <gtest/gtest.h>

#include <cmath>

#include "config/case_file.hpp"
#include "dem/film/steady_state.hpp"
#include "dem/scene/centrec_scene.hpp"

using namespace centrec;

TEST(QuickstartSteadyState, OutletMassFlowConvergesToInlet) {
  const config::CaseFile cf = config::read_case_file(std::string(CENTREC_SOURCE_DIR) + "/cases/quickstart.yaml");
  ASSERT_TRUE(cf.dem.has_value());
  dem::scene::CentrecScene scene(cf.dem->scene);
  const double duration = cf.dem->run.duration + 3.0 * scene.turn_period();
  scene.advance(duration);
  const auto& log = scene.mass_flow_log();
  std::vector<double> t, in, out;
  for (std::size_t k = 1; k < log.size(); ++k) {
    const double h = log[k].time - log[k - 1].time;
    t.push_back(log[k].time);
    in.push_back((log[k].fed - log[k - 1].fed) / h);
    out.push_back((log[k].out - log[k - 1].out) / h);
  }
  film::SteadyStateCriterion crit;
  crit.window = 3.0 * scene.turn_period();
  crit.tolerance = 0.08;
  const auto ss = film::find_steady_state(t.data(), in.data(), out.data(), t.size(), crit);
  // The last window's means, whatever the first steady window was.
  const auto& last = log.back();
  std::size_t k = log.size() - 1;
  while (k > 0 && last.time - log[k].time < crit.window) --k;
  const double w = last.time - log[k].time;
  const double rin = (last.fed - log[k].fed) / w, rout = (last.out - log[k].out) / w;
  std::printf("quickstart: steady %s at %.3f s; last %.3f s: inlet %.3f g/s, outlet %.3f g/s (%.1f %%), holdup %lld\n",
              ss.steady ? "yes" : "no", ss.time, w, rin * 1e3, rout * 1e3, 100.0 * (rout / rin - 1.0),
              static_cast<long long>(scene.free_particles()));
  EXPECT_TRUE(ss.steady);
  EXPECT_NEAR(rout / rin, 1.0, 0.10);
}
