// The dispersion estimator on synthetic random walks of known, depth-dependent D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "dem/film/dispersion.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double d = 1.2e-3, R = 50 * d;
// Known D(w), m^2/s, and a radial drift, m/s (away from the wall).
double D_of(double w) { return 2e-7 * (1.0 + 0.5 * w / d); }
constexpr double drift = 2e-3;
}  // namespace

TEST(Dispersion, RecoversKnownDiffusivityDespiteDrift) {
  const DrumFrame f = paper_view_frame(R, 0.2);
  WallDistanceBins b;
  b.particle_diameter = d;
  b.width_d = 1.0;
  b.count = 8;
  DispersionEstimator est(f, b);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double tau = 0.01;
  for (int pair = 0; pair < 3; ++pair) {
    Particles a, e;
    a.time = 1.0 + pair;
    e.time = a.time + tau;
    const int n = 120000;
    for (int i = 0; i < n; ++i) {
      const double w = (1.0 + 6.0 * u(rng)) * d, th = 2 * M_PI * u(rng), z = 0.2 * u(rng);
      a.add((R - w) * std::cos(th), (R - w) * std::sin(th), z, d / 2);
      a.id.back() = 1000000 * pair + i;
      // Radial step: drift plus Gaussian of variance 2 D(w0) tau; the angle changes too.
      const double r1 = (R - w) - drift * tau + std::sqrt(2 * D_of(w) * tau) * gauss(rng);
      const double th1 = th + 0.05 * u(rng);
      if (u(rng) < 0.05) continue;  // 5 % left the drum in between
      e.add(r1 * std::cos(th1), r1 * std::sin(th1), z, d / 2);
      e.id.back() = 1000000 * pair + i;
    }
    // The end snapshot in another order: matching must go by id.
    std::vector<std::size_t> order(e.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    Particles s;
    s.time = e.time;
    for (std::size_t i : order) {
      s.add(e.x[i], e.y[i], e.z[i], e.radius[i]);
      s.id.back() = e.id[i];
    }
    est.add_pair(a.view(), s.view());
  }
  const auto res = est.result();
  for (int k = 1; k < 7; ++k) {
    // The bin's true D is the mean of D(w) over the uniform starts in it: D at its centre.
    const double expect = D_of(res[k].wall_distance_d * d);
    std::printf("w=%.1f d: D=%.4e m^2/s (true %.4e, %+.2f %%, spread over %zu pairs %.1e), drift %.5f m/s (true "
                "%.5f), %zu samples\n",
                res[k].wall_distance_d, res[k].coefficient, expect, 100 * (res[k].coefficient / expect - 1),
                res[k].pairs, res[k].coefficient_std, res[k].drift, -drift, res[k].samples);
    EXPECT_NEAR(res[k].coefficient / expect, 1.0, 0.03) << k;
    EXPECT_NEAR(res[k].drift, -drift, 0.05 * drift) << k;
    EXPECT_EQ(res[k].pairs, 3u);
  }
  EXPECT_EQ(res[0].samples, 0u);
  EXPECT_TRUE(std::isnan(res[0].coefficient));
}

TEST(Dispersion, RejectsMixedLagsAndBackwardPairs) {
  const DrumFrame f = paper_view_frame(R, 0.2);
  WallDistanceBins b;
  b.particle_diameter = d;
  DispersionEstimator est(f, b);
  Particles a, e;
  a.add(R - d, 0, 0, d / 2);
  e.add(R - d, 0, 0, d / 2);
  e.time = 0.01;
  est.add_pair(a.view(), e.view());
  e.time = 0.02;
  EXPECT_THROW(est.add_pair(a.view(), e.view()), std::invalid_argument);
  EXPECT_THROW(est.add_pair(e.view(), a.view()), std::invalid_argument);
}
