// (c) A sphere resting on an incline (a plane wall, gravity tilted by theta).
// Rolling locked (very large mu_r): it is a block, held iff tan(theta) <= mu, sliding with
// a = g (sin - mu cos) otherwise. EPSD2 rolling with mu_r and ample sliding friction: the
// static balance F_t = m g sin(theta), F_t R = M_r <= mu_r R |Fn| holds iff tan(theta) <= mu_r;
// above it the sphere rolls with a = (5/7) g (sin - mu_r cos). CDT rolling (a constant
// torque mu_r R kn delta against the spin, dem/rolling_models.hpp) gives the same rolling
// acceleration above the limit (kn delta = m g cos once the sphere sits at its static
// overlap).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "dem_test_support.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

namespace {

// Down-slope acceleration of the sphere's centre over 0.05..0.15 s after release, m/s^2.
// roll_history: if given, |the wall contact's rolling history| at the end, N m.
double downslope_acceleration(double tan_theta, double mu, double mu_r, RollingModel model = RollingModel::epsd2,
                              double* roll_history = nullptr) {
  const double g = 9.81, th = std::atan(tan_theta);
  const Vec3 gravity{g * std::sin(th), 0.0, -g * std::cos(th)};  // slope = the plane z = 0, down = +x
  Simulation sim(quiet_config(2e-6, gravity));
  const MaterialId grain = use_paper_material(sim, PairInteraction{0.3, mu, mu_r, model});
  sim.add_wall(Wall::plane({0, 0, 0}, {0, 0, 1}, grain));
  // Start at the static Hertz overlap under the normal load so the sphere does not bounce.
  const double m = sphere_mass(kRadius), E = 5e6 / (1 - 0.09);
  const double load = m * g * std::cos(th);
  const double delta = std::pow(load / ((4.0 / 3.0) * E * std::sqrt(kRadius)), 2.0 / 3.0);
  sim.add_particle({grain, kRadius, {0, 0, kRadius - delta}, {}, {}});
  sim.step(25000);  // 0.05 s
  const double x0 = sim.positions()[0].x, v0 = sim.velocities()[0].x;
  sim.step(50000);  // 0.1 s
  const double t = 0.1, x1 = sim.positions()[0].x;
  if (roll_history) *roll_history = norm(sim.wall_history(0, 0).roll);
  return 2.0 * (x1 - x0 - v0 * t) / (t * t);
}

}  // namespace

TEST(Incline, SlidesIffTanThetaExceedsMu) {
  const double mu = 0.5, g = 9.81;
  for (double tan_theta : {0.45, 0.55}) {
    const double th = std::atan(tan_theta);
    const double a = downslope_acceleration(tan_theta, mu, 1000.0);
    const double expected = tan_theta > mu ? g * (std::sin(th) - mu * std::cos(th)) : 0.0;
    std::printf("(c) rolling locked, mu = %.2f, tan = %.2f: a = %.5f m/s^2, Coulomb block %.5f m/s^2 "
                "(tolerance 2 %% of g sin)\n",
                mu, tan_theta, a, expected);
    EXPECT_NEAR(a, expected, 0.02 * g * std::sin(th));
  }
}

TEST(Incline, Epsd2HoldsBelowRollingLimitAndRollsAbove) {
  const double mu = 1.0, mu_r = 0.26, g = 9.81;
  for (double tan_theta : {0.23, 0.30}) {
    const double th = std::atan(tan_theta);
    const double a = downslope_acceleration(tan_theta, mu, mu_r);
    const double expected = tan_theta > mu_r ? (5.0 / 7.0) * g * (std::sin(th) - mu_r * std::cos(th)) : 0.0;
    std::printf("(c) EPSD2 mu_r = %.2f, tan = %.2f: a = %.5f m/s^2, theory %.5f m/s^2 (tolerance 3 %% of g sin)\n",
                mu_r, tan_theta, a, expected);
    EXPECT_NEAR(a, expected, 0.03 * g * std::sin(th));
  }
}

TEST(Incline, CdtRollsAboveTheRollingLimitAsTheConstantTorqueGives) {
  const double mu = 1.0, g = 9.81;
  for (const auto& [mu_r, tan_theta] : {std::pair{0.1, 0.3}, std::pair{0.26, 0.4}}) {
    const double th = std::atan(tan_theta);
    double cdt_history = 0.0, epsd2_history = 0.0;
    const double a = downslope_acceleration(tan_theta, mu, mu_r, RollingModel::cdt, &cdt_history);
    const double with_epsd2 = downslope_acceleration(tan_theta, mu, mu_r, RollingModel::epsd2, &epsd2_history);
    const double expected = (5.0 / 7.0) * g * (std::sin(th) - mu_r * std::cos(th));
    const double free_rolling = (5.0 / 7.0) * g * std::sin(th);
    std::printf("(c) CDT mu_r = %.2f, tan = %.2f: a = %.5f m/s^2, theory %.5f (EPSD2 %.5f, no rolling resistance "
                "%.5f; tolerance 3 %% of g sin); rolling history CDT %.3g, EPSD2 %.3g N m\n",
                mu_r, tan_theta, a, expected, with_epsd2, free_rolling, cdt_history, epsd2_history);
    EXPECT_EQ(cdt_history, 0.0);  // CDT keeps no spring: the model in use is CDT
    EXPECT_GT(epsd2_history, 0.0);
    EXPECT_NEAR(a, expected, 0.03 * g * std::sin(th));
    EXPECT_GT(free_rolling - a, 0.5 * (free_rolling - expected));  // the torque acted
  }
}
