#include "film_top_radiation.hpp"

#include <cmath>
#include <stdexcept>

#include "cavity_radiation.hpp"
#include "solar_extinction.hpp"

namespace centrec::thermal {

namespace {
constexpr double kPi = 3.14159265358979323846;

double diffuse_sphere_phase(double cos_theta) {
  const double th = std::acos(std::fmax(-1.0, std::fmin(1.0, cos_theta)));
  return 8.0 / (3.0 * kPi) * (std::sin(th) - th * std::cos(th));
}

double backscatter_by_quadrature() {
  // b = int_0^1 d mu' int_-1^0 d mu (1/2) (1/2pi) int_0^2pi p(cos Theta) d phi with
  // cos Theta = mu mu' + sqrt(1 - mu^2) sqrt(1 - mu'^2) cos phi (incident directions mu' > 0
  // weighted by solid angle, as the scattering rate is). Midpoint rule; p = 1 gives 1/2.
  const int n = 96, m = 96;
  double sum = 0.0;
  for (int a = 0; a < n; ++a) {
    const double mu_in = (a + 0.5) / n, s_in = std::sqrt(1.0 - mu_in * mu_in);
    for (int c = 0; c < n; ++c) {
      const double mu = -(c + 0.5) / n, s = std::sqrt(1.0 - mu * mu);
      double az = 0.0;
      for (int k = 0; k < m; ++k)
        az += diffuse_sphere_phase(mu * mu_in + s * s_in * std::cos(2.0 * kPi * (k + 0.5) / m));
      sum += 0.5 * az / m;
    }
  }
  return sum / (static_cast<double>(n) * n);
}
}  // namespace

double diffuse_sphere_backscatter_fraction() {
  static const double b = backscatter_by_quadrature();
  return b;
}

TwoFluxLayer two_flux_layer(double phi, double L, double d, double eps, double b) {
  if (!(phi > 0.0) || !(L > 0.0)) return {0.0, 1.0};
  const double beta = 1.0 / (extinction_depth_d_from_phi(phi) * d);
  const double kappa = eps * beta, back = b * (1.0 - eps) * beta;
  // q+ and q- couple through a = 2 (kappa + b sigma_s) and c = 2 b sigma_s; the eigenvalue
  // gamma = sqrt(a^2 - c^2) and the semi-infinite reflectance rho = c / (a + gamma) give
  //   R = rho (1 - x^2) / (1 - rho^2 x^2),  T = (1 - rho^2) x / (1 - rho^2 x^2),  x = exp(-gamma L).
  const double a = 2.0 * (kappa + back), c = 2.0 * back;
  const double gamma = 2.0 * std::sqrt(kappa * (kappa + 2.0 * back));
  const double rho = c / (a + gamma);
  const double x = std::exp(-gamma * L), x2 = x * x;
  const double den = 1.0 - rho * rho * x2;
  return {rho * -std::expm1(-2.0 * gamma * L) / den, (1.0 - rho * rho) * x / den};
}

TwoFluxColumn two_flux_column(const std::vector<double>& phi, double deta, double d, double eps, double b) {
  const int n = static_cast<int>(phi.size());
  if (n == 0) throw std::invalid_argument("two-flux column: no cells");
  // Unknowns: u_f = q+ and w_f = q- at faces f = 0..n (face f below cell f), ordered
  // (u_0, w_0, u_1, w_1, ...). Equations: u_0 = E_below; w_n = H; per cell j
  //   u_{j+1} - T_j u_j - R_j w_{j+1} = e_j E_j,   w_j - T_j w_{j+1} - R_j u_j = e_j E_j.
  const int N = 2 * (n + 1), ns = n + 2;
  std::vector<double> A(static_cast<std::size_t>(N) * N, 0.0), rhs(static_cast<std::size_t>(N) * ns, 0.0);
  auto at = [&](int row, int col) -> double& { return A[static_cast<std::size_t>(row) * N + col]; };
  auto src = [&](int row, int k) -> double& { return rhs[static_cast<std::size_t>(row) * ns + k]; };
  const int U = 0, W = 1;
  at(0, U) = 1.0;
  src(0, n) = 1.0;
  for (int j = 0; j < n; ++j) {
    const TwoFluxLayer l = two_flux_layer(phi[j], deta, d, eps, b);
    const double e = std::fmax(0.0, 1.0 - l.R - l.T);
    const int r1 = 1 + 2 * j, r2 = 2 + 2 * j;
    at(r1, 2 * (j + 1) + U) = 1.0;
    at(r1, 2 * j + U) = -l.T;
    at(r1, 2 * (j + 1) + W) = -l.R;
    src(r1, j) = e;
    at(r2, 2 * j + W) = 1.0;
    at(r2, 2 * (j + 1) + W) = -l.T;
    at(r2, 2 * j + U) = -l.R;
    src(r2, j) = e;
  }
  at(N - 1, 2 * n + W) = 1.0;
  src(N - 1, n + 1) = 1.0;
  const std::vector<double> inv = dense_inverse(std::move(A), N);
  std::vector<double> flux(static_cast<std::size_t>(N) * ns, 0.0);  // face flux per unit source
  for (int r = 0; r < N; ++r)
    for (int q = 0; q < N; ++q) {
      const double v = inv[static_cast<std::size_t>(r) * N + q];
      if (v == 0.0) continue;
      for (int k = 0; k < ns; ++k)
        flux[static_cast<std::size_t>(r) * ns + k] += v * rhs[static_cast<std::size_t>(q) * ns + k];
    }
  auto f = [&](int face, int dir, int k) { return flux[static_cast<std::size_t>(2 * face + dir) * ns + k]; };
  TwoFluxColumn col;
  col.n = n;
  col.absorbed.assign(static_cast<std::size_t>(n) * ns, 0.0);
  col.below.resize(ns);
  col.leaving.resize(ns);
  for (int k = 0; k < ns; ++k) {
    for (int j = 0; j < n; ++j)
      col.absorbed[static_cast<std::size_t>(j) * ns + k] =
          (f(j, U, k) + f(j + 1, W, k)) - (f(j + 1, U, k) + f(j, W, k));
    col.below[k] = f(0, W, k) - f(0, U, k);
    col.leaving[k] = f(n, U, k);
  }
  return col;
}

double maxwell_dispersion_conductivity(double k_s, double k_g, double phi) {
  const double kappa = k_s / k_g;
  return k_g * (2.0 + kappa + 2.0 * phi * (kappa - 1.0)) / (2.0 + kappa - phi * (kappa - 1.0));
}

}  // namespace centrec::thermal
