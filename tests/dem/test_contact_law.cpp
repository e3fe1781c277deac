// (g) The contact law called directly: force on j equals minus force on i, and the
// torques match, for random pair states seen from either side.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "dem/contact_law.hpp"

using namespace centrec::dem;

namespace {

Vec3 random_vec(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {scale * u(rng), scale * u(rng), scale * u(rng)};
}

}  // namespace

TEST(ContactLaw, ActionEqualsReactionForRandomStates) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_force = 0.0, worst_torque = 0.0;
  int sliding = 0;
  const int trials = 2000;
  for (int t = 0; t < trials; ++t) {
    Material ma{1e6 + 1e7 * u(rng), 0.2 + 0.2 * u(rng), 2000 + 2000 * u(rng)};
    Material mb{1e6 + 1e7 * u(rng), 0.2 + 0.2 * u(rng), 2000 + 2000 * u(rng)};
    PairInteraction p{0.1 + 0.9 * u(rng), 2.0 * u(rng), 0.5 * u(rng)};
    const PairConstants c = make_pair_constants(ma, mb, p);
    const double ri = 1e-4 + 1e-3 * u(rng), rj = 1e-4 + 1e-3 * u(rng);
    const double mi = 1e-6 + 1e-5 * u(rng), mj = 1e-6 + 1e-5 * u(rng);
    const double delta = 0.02 * std::min(ri, rj) * u(rng);
    const Vec3 n = normalized(random_vec(rng, 1.0));
    const Vec3 vi = random_vec(rng, 1.0), vj = random_vec(rng, 1.0);
    const Vec3 wi = random_vec(rng, 500.0), wj = random_vec(rng, 500.0);
    ContactHistory h;
    h.shear = random_vec(rng, 1e-5);
    h.shear -= dot(h.shear, n) * n;
    h.roll = random_vec(rng, 1e-7);
    const double dt = 1e-6;

    const double arm_i = ri - 0.5 * delta, arm_j = rj - 0.5 * delta;
    // n points from j to i
    ContactInput from_i{delta,           n, contact_velocity(vi - vj, wi, wj, arm_i, arm_j, n), wi - wj,
                        ri * rj / (ri + rj), mi * mj / (mi + mj), arm_i, arm_j};
    ContactInput from_j = from_i;  // the same pair with the roles swapped
    from_j.n = -n;
    from_j.arm_i = from_i.arm_j;
    from_j.arm_j = from_i.arm_i;
    from_j.v_contact = contact_velocity(vj - vi, wj, wi, from_j.arm_i, from_j.arm_j, -n);
    from_j.w_rel = wj - wi;
    ContactHistory hj{-1.0 * h.shear, -1.0 * h.roll};  // history is antisymmetric too

    const ContactResult a = evaluate_contact(c, from_i, h, dt);
    const ContactResult b = evaluate_contact(c, from_j, hj, dt);
    sliding += a.sliding;
    const double fscale = norm(a.force) + 1e-300;
    const double tscale = norm(a.torque_i) + norm(a.torque_j) + 1e-300;
    worst_force = std::max(worst_force, norm(a.force + b.force) / fscale);
    worst_torque = std::max(worst_torque, (norm(a.torque_i - b.torque_j) + norm(a.torque_j - b.torque_i)) / tscale);
    EXPECT_EQ(a.sliding, b.sliding);
    EXPECT_NEAR(norm(a.history.shear + b.history.shear), 0.0, 1e-12 * (norm(a.history.shear) + 1e-300));
  }
  std::printf("(g) %d random pair states (%d sliding): max |F_i + F_j|/|F_i| = %.2e, torque mismatch %.2e "
              "(tolerance 1e-12)\n",
              trials, sliding, worst_force, worst_torque);
  EXPECT_LT(worst_force, 1e-12);
  EXPECT_LT(worst_torque, 1e-12);
  EXPECT_GT(sliding, 0);
  EXPECT_LT(sliding, trials);
}
