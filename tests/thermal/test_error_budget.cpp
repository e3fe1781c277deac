// The error budget's statistics (thermal/error_budget.hpp), each against an independent
// calculation:
//   - the Latin hypercube puts exactly one point in each of the n strata of every dimension,
//     is the same for the same seed and differs for another;
//   - the one-at-a-time variance (y_hi - y_lo)^2 / 12 equals the variance of a linear
//     function of a uniform input computed by quadrature (1e-12 relative);
//   - the linear fit recovers the coefficients of an exactly linear output (1e-10) with
//     R^2 = 1, and on an output with a quadratic part it gives R^2 below 1;
//   - the sample statistics match hand-computed mean, sd and quantiles (1e-12).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "thermal/error_budget.hpp"

using namespace centrec::thermal;

TEST(ErrorBudget, LatinHypercubeStratifiesEveryDimension) {
  const int n = 40, k = 8;
  const auto d = latin_hypercube(n, k, 12345);
  ASSERT_EQ(d.size(), static_cast<std::size_t>(n));
  for (int j = 0; j < k; ++j) {
    std::vector<int> count(n, 0);
    for (int s = 0; s < n; ++s) {
      ASSERT_GE(d[s][j], 0.0);
      ASSERT_LT(d[s][j], 1.0);
      ++count[static_cast<int>(std::floor(d[s][j] * n))];
    }
    for (int c : count) EXPECT_EQ(c, 1) << "dimension " << j;
  }
  const auto again = latin_hypercube(n, k, 12345), other = latin_hypercube(n, k, 12346);
  EXPECT_EQ(d, again);
  EXPECT_NE(d, other);
  std::printf("first sample, seed 12345: %.6f %.6f %.6f ...; seed 12346: %.6f %.6f %.6f ...\n", d[0][0], d[0][1],
              d[0][2], other[0][0], other[0][1], other[0][2]);
}

TEST(ErrorBudget, OneAtATimeVarianceIsThatOfALinearFunctionOfAUniformInput) {
  const double lo = 0.8, hi = 3.6, a = 2.5, b = -7.0;  // y = a + b x, x ~ U(lo, hi)
  const int m = 200000;
  double s1 = 0.0, s2 = 0.0;  // midpoint quadrature of E[y], E[y^2]
  for (int i = 0; i < m; ++i) {
    const double y = a + b * (lo + (i + 0.5) * (hi - lo) / m);
    s1 += y / m;
    s2 += y * y / m;
  }
  const double quadrature = s2 - s1 * s1, oat = uniform_oat_variance(a + b * lo, a + b * hi);
  std::printf("variance: one at a time %.12g, quadrature %.12g (relative %.2e, tolerance 1e-9)\n", oat, quadrature,
              oat / quadrature - 1.0);
  EXPECT_NEAR(oat / quadrature, 1.0, 1e-9);
}

TEST(ErrorBudget, LinearFitRecoversCoefficients) {
  const auto u = latin_hypercube(30, 3, 7);
  std::vector<std::vector<double>> x;
  std::vector<double> y, yq;
  for (const auto& p : u) {
    const std::vector<double> v = {0.9 + 0.2 * p[0], 1.0 + 2.0 * p[1], 0.8 + 2.8 * p[2]};
    x.push_back(v);
    y.push_back(1000.0 - 200.0 * v[0] + 0.5 * v[1] - 5.0 * v[2]);
    yq.push_back(y.back() + 30.0 * (v[0] - 1.0) * (v[0] - 1.0) * 1e3);
  }
  const LinearShares f = linear_shares(x, y);
  std::printf("coefficients %.10f %.10f %.10f (exact -200, 0.5, -5), intercept %.8f, R^2 %.12f\n", f.coefficient[0],
              f.coefficient[1], f.coefficient[2], f.intercept, f.r2);
  EXPECT_NEAR(f.coefficient[0], -200.0, 1e-8);
  EXPECT_NEAR(f.coefficient[1], 0.5, 1e-10);
  EXPECT_NEAR(f.coefficient[2], -5.0, 1e-10);
  EXPECT_NEAR(f.intercept, 1000.0, 1e-8);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  const LinearShares q = linear_shares(x, yq);
  std::printf("with a quadratic part: R^2 %.6f\n", q.r2);
  EXPECT_LT(q.r2, 0.999);
  EXPECT_THROW(linear_shares({{1.0}, {2.0}}, {1.0, 2.0}), std::invalid_argument);  // not more samples than coefficients
}

TEST(ErrorBudget, SampleStatsMatchHandValues) {
  const SampleStats s = sample_stats({4.0, 1.0, 3.0, 2.0, 5.0});
  // mean 3, sd sqrt(10/4); p05 at rank 0.2 -> 1.2, p95 at rank 3.8 -> 4.8
  std::printf("mean %.3f sd %.6f min %.1f max %.1f p05 %.3f p95 %.3f\n", s.mean, s.sd, s.min, s.max, s.p05, s.p95);
  EXPECT_NEAR(s.mean, 3.0, 1e-12);
  EXPECT_NEAR(s.sd, std::sqrt(2.5), 1e-12);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 5.0);
  EXPECT_NEAR(s.p05, 1.2, 1e-12);
  EXPECT_NEAR(s.p95, 4.8, 1e-12);
}
