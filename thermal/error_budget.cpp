#include "error_budget.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace centrec::thermal {

namespace {
// A double in [0, 1) from the top 53 bits: the same on every platform (std's distributions
// are not specified bit for bit).
double unit_double(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
// An index in [0, n) by rejection, free of modulo bias and platform independent.
std::size_t unit_index(std::mt19937_64& g, std::size_t n) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
  std::uint64_t v;
  do v = g();
  while (v >= limit);
  return static_cast<std::size_t>(v % n);
}
}  // namespace

std::vector<std::vector<double>> latin_hypercube(int n, int k, std::uint64_t seed) {
  if (n < 1 || k < 1) throw std::invalid_argument("Latin hypercube: needs at least one sample and one dimension");
  std::mt19937_64 g(seed);
  std::vector<std::vector<double>> design(n, std::vector<double>(k));
  std::vector<std::size_t> strata(n);
  for (int d = 0; d < k; ++d) {
    std::iota(strata.begin(), strata.end(), std::size_t{0});
    for (std::size_t i = strata.size() - 1; i > 0; --i) std::swap(strata[i], strata[unit_index(g, i + 1)]);  // Fisher-Yates
    for (int s = 0; s < n; ++s) design[s][d] = (static_cast<double>(strata[s]) + unit_double(g)) / n;
  }
  return design;
}

double uniform_oat_variance(double y_lo, double y_hi) { return (y_hi - y_lo) * (y_hi - y_lo) / 12.0; }

LinearShares linear_shares(const std::vector<std::vector<double>>& x, const std::vector<double>& y) {
  const std::size_t n = y.size(), k = x.empty() ? 0 : x.front().size();
  if (x.size() != n || n <= k + 1)
    throw std::invalid_argument("linear shares: need more samples (" + std::to_string(n) + ") than coefficients (" +
                                std::to_string(k + 1) + ")");
  // Standardised inputs and output (centred, over their sd): the normal equations then give
  // the SRC_i directly and are well scaled whatever the inputs' units.
  std::vector<double> mx(k), sx(k);
  for (std::size_t i = 0; i < k; ++i) {
    std::vector<double> xi(n);
    for (std::size_t s = 0; s < n; ++s) xi[s] = x[s][i];
    const SampleStats st = sample_stats(xi);
    if (!(st.sd > 0)) throw std::invalid_argument("linear shares: input " + std::to_string(i) + " does not vary");
    mx[i] = st.mean;
    sx[i] = st.sd;
  }
  const SampleStats sy = sample_stats(y);
  LinearShares r;
  r.src.assign(k, 0.0);
  r.coefficient.assign(k, 0.0);
  if (!(sy.sd > 0)) {  // a constant output: no input explains anything, the fit is exact
    r.intercept = sy.mean;
    r.r2 = 1.0;
    return r;
  }
  // G = Z^T Z, c = Z^T w, Z the standardised inputs, w the standardised output.
  std::vector<std::vector<double>> G(k, std::vector<double>(k + 1, 0.0));
  for (std::size_t s = 0; s < n; ++s) {
    const double w = (y[s] - sy.mean) / sy.sd;
    for (std::size_t i = 0; i < k; ++i) {
      const double zi = (x[s][i] - mx[i]) / sx[i];
      for (std::size_t j = 0; j < k; ++j) G[i][j] += zi * (x[s][j] - mx[j]) / sx[j];
      G[i][k] += zi * w;
    }
  }
  // Gaussian elimination with partial pivoting (k is the number of inputs, about ten).
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t piv = c;
    for (std::size_t i = c + 1; i < k; ++i)
      if (std::abs(G[i][c]) > std::abs(G[piv][c])) piv = i;
    std::swap(G[c], G[piv]);
    if (!(std::abs(G[c][c]) > 1e-12 * n))
      throw std::invalid_argument("linear shares: the inputs are linearly dependent over the samples");
    for (std::size_t i = c + 1; i < k; ++i) {
      const double f = G[i][c] / G[c][c];
      for (std::size_t j = c; j <= k; ++j) G[i][j] -= f * G[c][j];
    }
  }
  for (std::size_t c = k; c-- > 0;) {
    double v = G[c][k];
    for (std::size_t j = c + 1; j < k; ++j) v -= G[c][j] * r.src[j];
    r.src[c] = v / G[c][c];
  }
  r.intercept = sy.mean;
  for (std::size_t i = 0; i < k; ++i) {
    r.coefficient[i] = r.src[i] * sy.sd / sx[i];
    r.intercept -= r.coefficient[i] * mx[i];
  }
  double ss_res = 0.0, ss_tot = 0.0;
  for (std::size_t s = 0; s < n; ++s) {
    double fit = r.intercept;
    for (std::size_t i = 0; i < k; ++i) fit += r.coefficient[i] * x[s][i];
    ss_res += (y[s] - fit) * (y[s] - fit);
    ss_tot += (y[s] - sy.mean) * (y[s] - sy.mean);
  }
  r.r2 = 1.0 - ss_res / ss_tot;
  return r;
}

SampleStats sample_stats(const std::vector<double>& y) {
  SampleStats s;
  if (y.empty()) return s;
  const double n = static_cast<double>(y.size());
  s.mean = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double ss = 0.0;
  for (double v : y) ss += (v - s.mean) * (v - s.mean);
  s.sd = y.size() > 1 ? std::sqrt(ss / (n - 1.0)) : 0.0;
  std::vector<double> o = y;
  std::sort(o.begin(), o.end());
  s.min = o.front();
  s.max = o.back();
  auto quantile = [&](double p) {
    const double at = p * (n - 1.0);
    const std::size_t i = static_cast<std::size_t>(std::floor(at));
    const double f = at - static_cast<double>(i);
    return i + 1 < o.size() ? o[i] + f * (o[i + 1] - o[i]) : o[i];
  };
  s.p05 = quantile(0.05);
  s.p95 = quantile(0.95);
  return s;
}

}  // namespace centrec::thermal
