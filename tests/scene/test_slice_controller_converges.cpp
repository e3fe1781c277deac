// Slice holdup controller (dem/scene/slice_controller.hpp), label slow (about 10 turns of a
// 4 d slice; minutes on 2 busy cores): a controlled slice started 30 % under the holdup of
// a reference slice, with the reference's measured axial mass flow as its target,
// converges to that flow and so to about the reference holdup.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/scene/centrec_scene.hpp"
#include "tests/scene/slice_case.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

TEST(SliceController, ControlledSliceConvergesToTheTargetFlow) {
  // Reference: 1100 particles, uncontrolled; its mean axial flow over turns 2-4 is the target.
  CentrecScene ref(centrec::testing::controlled_slice(1100, 0.0));
  const double turn = ref.turn_period();
  ref.advance(1.5 * turn);
  double sum = 0.0;
  std::size_t n = 0;
  const std::size_t first = ref.mass_flow_log().size();
  ref.advance(2.0 * turn);
  for (std::size_t k = first; k < ref.mass_flow_log().size(); ++k, ++n) sum += ref.mass_flow_log()[k].axial_flow;
  const double target = sum / static_cast<double>(n);
  const std::int64_t n_ref = ref.free_particles();

  // Controlled: starts at 770 particles (30 % under), one-turn windows.
  CentrecScene ctl(centrec::testing::controlled_slice(770, target));
  ctl.advance(8.0 * turn);
  const auto& log = ctl.controller_log();
  ASSERT_GE(log.size(), 7u);
  for (const auto& w : log)
    std::printf("  t = %.3f s  mdot %.3f g/s  particles %lld (%+lld)\n", w.time, w.mass_flow * 1e3,
                static_cast<long long>(w.particles), static_cast<long long>(w.change));
  double late = 0.0;
  for (std::size_t k = log.size() - 3; k < log.size(); ++k) late += log[k].mass_flow / 3.0;
  const double err = (late - target) / target;
  const double holdup_err = static_cast<double>(ctl.free_particles() - n_ref) / static_cast<double>(n_ref);
  std::printf("target %.3f g/s (reference, %lld particles); controlled: last 3 windows %.3f g/s (%+.1f %%), "
              "%lld particles (%+.1f %% vs reference)\n",
              target * 1e3, static_cast<long long>(n_ref), late * 1e3, 100 * err,
              static_cast<long long>(ctl.free_particles()), 100 * holdup_err);
  EXPECT_GT(target, 0.0);
  EXPECT_LT(std::fabs(err), 0.20);         // tolerance: 20 % of the target flow (turn-to-turn noise ~10 %)
  EXPECT_LT(std::fabs(holdup_err), 0.10);  // and the holdup it settles to, within 10 %
  EXPECT_GT(ctl.free_particles(), 770);    // it did add particles
}
