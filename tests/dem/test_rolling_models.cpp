// The rolling models of dem/rolling_models.hpp against hand calculations
// (docs/dem_physics.md "Rolling resistance"), and the table's invariants. SDS: a pair with
// n = z, R* = 1 mm, |F_n| = 2 N, mu_r = 0.1 (cap mu_r |F_n| = 0.2 N, torque cap
// mu_r R* |F_n| = 2e-4 N m), k_roll = 100 N/m, dt = 1e-5 s, spinning at w_rel = 10 rad/s
// about x: rolling velocity v_r = R* (w_rel x n) = (0, -0.01, 0) m/s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "dem/contact_law.hpp"
#include "dem/rolling_models.hpp"

using namespace centrec::dem;

namespace {

constexpr double kR = 1e-3, kFn = 2.0, kMuR = 0.1, kDt = 1e-5;
const Vec3 kN{0.0, 0.0, 1.0}, kSpin{10.0, 0.0, 0.0};

RollingOut<Vec3> sds(double k, double gamma, Vec3 s_old) {
  const double coefficients[2] = {k, gamma};
  // kt, kn and delta are not read by SDS.
  return rolling_torque(RollingModel::sds,
                        rolling_input(0.0, 0.0, 0.0, kR, kMuR, kFn, kN, kSpin, s_old, coefficients, kDt));
}

void expect_near(Vec3 got, Vec3 want, double tol, const char* what) {
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
  EXPECT_NEAR(got.z, want.z, tol) << what;
}

}  // namespace

// Spring: s = (0, -1e-5, 0) + dt v_r = (0, -1.01e-5, 0) m, F_r = -k s = (0, 1.01e-3, 0) N
// (under the 0.2 N cap), M = R* F_r x n = (1.01e-6, 0, 0) N m = k R* |s|: on i -M, against
// its spin.
TEST(RollingModels, SdsSpringIsKRollTimesTheRollingDisplacement) {
  const RollingOut<Vec3> r = sds(100.0, 0.0, {0.0, -1e-5, 0.0});
  std::printf("sds spring: torque (%.6g, %.3g, %.3g) N m, history (%.3g, %.6g, %.3g) m\n", r.torque.x, r.torque.y,
              r.torque.z, r.history.x, r.history.y, r.history.z);
  expect_near(r.torque, {1.01e-6, 0.0, 0.0}, 1e-18, "torque");
  expect_near(r.history, {0.0, -1.01e-5, 0.0}, 1e-18, "history");
}

// Dashpot: gamma_roll = 0.01 N s/m adds -gamma v_r = (0, 1e-4, 0) N: F_r = (0, 1.11e-3, 0) N,
// M = (1.11e-6, 0, 0) N m; the spring's displacement is as without it.
TEST(RollingModels, SdsDashpotAddsGammaRollTimesTheRollingVelocity) {
  const RollingOut<Vec3> r = sds(100.0, 0.01, {0.0, -1e-5, 0.0});
  std::printf("sds dashpot: torque (%.6g, %.3g, %.3g) N m\n", r.torque.x, r.torque.y, r.torque.z);
  expect_near(r.torque, {1.11e-6, 0.0, 0.0}, 1e-18, "torque");
  expect_near(r.history, {0.0, -1.01e-5, 0.0}, 1e-18, "history");
}

// Slider: s = (0, -0.0100001, 0) m gives |F_r| = 1.00011 N > 0.2 N: F_r held at 0.2 N along
// itself, M = mu_r R* |F_n| = 2e-4 N m, and s set to what leaves that force,
// -(0.2 / 100) y - (0.01 / 100) v_r = (0, -1.999e-3, 0) m.
TEST(RollingModels, SdsSliderCapsTheTorqueAtMuRTimesRTimesFn) {
  const RollingOut<Vec3> r = sds(100.0, 0.01, {0.0, -1e-2, 0.0});
  std::printf("sds slider: torque (%.6g, %.3g, %.3g) N m (cap %.6g), history (%.3g, %.6g, %.3g) m\n", r.torque.x,
              r.torque.y, r.torque.z, kMuR * kR * kFn, r.history.x, r.history.y, r.history.z);
  expect_near(r.torque, {kMuR * kR * kFn, 0.0, 0.0}, 1e-18, "torque");
  expect_near(r.history, {0.0, -1.999e-3, 0.0}, 1e-15, "history");
  // The displacement left gives the capped force again: -k s - gamma v_r = 0.2 N.
  EXPECT_NEAR(-100.0 * r.history.y - 0.01 * -0.01, kMuR * kFn, 1e-12);
}

// An old displacement with a normal part (the pair turned) is turned into the tangent plane
// with its length kept: (0, -1e-5, 1e-6) becomes (0, -sqrt(1.01e-10), 0) before the step.
TEST(RollingModels, SdsTurnsAnOldDisplacementIntoTheTangentPlane) {
  const RollingOut<Vec3> r = sds(100.0, 0.0, {0.0, -1e-5, 1e-6});
  const double s_y = -std::sqrt(1.01e-10) - 1e-7;
  expect_near(r.history, {0.0, s_y, 0.0}, 1e-18, "history");
  expect_near(r.torque, {-100.0 * kR * s_y, 0.0, 0.0}, 1e-18, "torque");
}

// Through the contact law: SDS, like every model, is skipped at mu_r = 0; at mu_r > 0 the
// torques on i and j are -M and +M of the kernel.
TEST(RollingModels, SdsInTheContactLaw) {
  const Material m{5e6, 0.3, 3560.0};
  PairInteraction p{0.46, 0.81, kMuR, RollingModel::sds, {100.0, 0.0}};
  const ContactInput in{1e-6, kN, {}, kSpin, kR, 1e-6, 1e-3, 1e-3};
  const ContactHistory old{{}, {0.0, -1e-5, 0.0}};
  const ContactResult with = evaluate_contact(make_pair_constants(m, m, p), in, old, kDt);
  const double coefficients[2] = {100.0, 0.0};
  const RollingOut<Vec3> r = rolling_torque(
      RollingModel::sds, rolling_input(0.0, 0.0, 0.0, kR, kMuR, with.fn, kN, kSpin, old.roll, coefficients, kDt));
  EXPECT_GT(norm(r.torque), 0.0);
  EXPECT_TRUE(with.torque_i == -r.torque);  // no sliding velocity: the rolling torque alone
  EXPECT_TRUE(with.torque_j == r.torque);
  EXPECT_TRUE(with.history.roll == r.history);
  p.rolling_friction = 0.0;
  const ContactResult without = evaluate_contact(make_pair_constants(m, m, p), in, old, kDt);
  EXPECT_EQ(without.torque_i.x, 0.0);
  EXPECT_TRUE(without.history.roll == Vec3{});
}

// The table: names unique, the defaults inside their own ranges, every model's kernel
// reachable by rolling_torque (a model without one does not compile).
TEST(RollingModels, TableRowsAreWhole) {
  std::set<std::string> names;
  for (const RollingModelInfo& i : kRollingModels) {
    EXPECT_TRUE(names.insert(i.name).second) << i.name;
    for_each_rolling_coefficient(i.model, [&](std::size_t, const RollingCoefficient& c) {
      const bool inside = c.lowest_open ? c.fallback > c.lowest : c.fallback >= c.lowest;
      EXPECT_TRUE(inside && c.fallback <= c.highest) << i.name << " " << c.key;
      EXPECT_TRUE(c.unit && c.meaning && c.lammps) << i.name << " " << c.key;
    });
    const RollingCoefficients k = default_rolling_coefficients(i.model);
    const RollingOut<Vec3> r = rolling_torque(
        i.model, rolling_input(1e3, 1e3, 1e-6, kR, kMuR, kFn, kN, kSpin, Vec3{0.0, -1e-6, 0.0}, k.data(), kDt));
    EXPECT_GT(r.torque.x * kSpin.x, 0.0) << i.name << ": the torque on i, -M, opposes its relative spin";
  }
}
