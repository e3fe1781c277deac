#pragma once
// The statistics of the error budget (docs/error_budget.md): a seeded Latin hypercube over
// the inputs' ranges, the variance shares of a one-at-a-time scan and of a linear fit to the
// hypercube's outputs, and the summary statistics of a sample. Plain functions on vectors;
// which inputs and how they enter the film model is the caller's (apps/runs/thermal_budget.*).
#include <cstdint>
#include <vector>

namespace centrec::thermal {

// n points in [0, 1)^k: in every dimension each of the n strata [i/n, (i+1)/n) holds exactly
// one point, at a uniform position inside it; the strata are paired across dimensions by
// independent random permutations (McKay, Beckman & Conover 1979, Technometrics 21, 239).
// Reproducible: the same (n, k, seed) gives the same design on every platform (mt19937_64
// with its own mapping to doubles and to permutation indices). design[sample][dimension].
std::vector<std::vector<double>> latin_hypercube(int n, int k, std::uint64_t seed);

// Variance of an output that is linear in an input drawn uniformly from [lo, hi], from the
// outputs at the two ends: (y_hi - y_lo)^2 / 12. Summed over the inputs, the one-at-a-time
// estimate of the output's variance; each term over the sum is that input's share.
double uniform_oat_variance(double y_lo, double y_hi);

// Least-squares fit y = b0 + sum_i b_i x_i over the samples (x[sample][input]); the
// standardised coefficients SRC_i = b_i sd(x_i) / sd(y) and R^2. For independent inputs and
// R^2 near 1, SRC_i^2 is input i's share of the variance of y (Saltelli et al. 2008, Global
// Sensitivity Analysis: The Primer, section 1.2.5). Throws std::invalid_argument if there are
// not more samples than coefficients or an input does not vary.
struct LinearShares {
  std::vector<double> coefficient;  // b_i, per unit of input i
  std::vector<double> src;          // standardised, SRC_i
  double intercept = 0.0, r2 = 0.0;
};
LinearShares linear_shares(const std::vector<std::vector<double>>& x, const std::vector<double>& y);

struct SampleStats {
  double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0;
  double p05 = 0.0, p95 = 0.0;  // empirical quantiles, linear between order statistics
};
SampleStats sample_stats(const std::vector<double>& y);

}  // namespace centrec::thermal
