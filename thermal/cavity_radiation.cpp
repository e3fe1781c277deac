#include "cavity_radiation.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace centrec::thermal {

// Gauss-Jordan elimination with partial pivoting (the enclosure matrix is diagonally
// dominant for reflectances < 1).
std::vector<double> dense_inverse(std::vector<double> A, int n) {
  std::vector<double> X(static_cast<std::size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i) X[static_cast<std::size_t>(i) * n + i] = 1.0;
  auto a = [&](int r, int c) -> double& { return A[static_cast<std::size_t>(r) * n + c]; };
  auto x = [&](int r, int c) -> double& { return X[static_cast<std::size_t>(r) * n + c]; };
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int r = k + 1; r < n; ++r)
      if (std::abs(a(r, k)) > std::abs(a(p, k))) p = r;
    if (!(std::abs(a(p, k)) > 0.0)) throw std::runtime_error("cavity enclosure: singular radiosity matrix");
    if (p != k)
      for (int c = 0; c < n; ++c) std::swap(a(p, c), a(k, c)), std::swap(x(p, c), x(k, c));
    const double inv = 1.0 / a(k, k);
    for (int c = 0; c < n; ++c) a(k, c) *= inv, x(k, c) *= inv;
    for (int r = 0; r < n; ++r) {
      if (r == k || a(r, k) == 0.0) continue;
      const double f = a(r, k);
      for (int c = 0; c < n; ++c) a(r, c) -= f * a(k, c), x(r, c) -= f * x(k, c);
    }
  }
  return X;
}

CavityEnclosure::CavityEnclosure(CavityViewFactors vf, std::vector<double> reflectance)
    : vf_(std::move(vf)), rho_(std::move(reflectance)) {
  const int n = surfaces(), P = vf_.aperture();
  if (static_cast<int>(rho_.size()) != n) throw std::invalid_argument("cavity enclosure: one reflectance per surface");
  for (double r : rho_)
    if (!(r >= 0 && r < 1)) throw std::invalid_argument("cavity enclosure: reflectances must be in [0, 1)");
  Fss_.resize(static_cast<std::size_t>(n) * n);
  Fsp_.resize(n);
  std::vector<double> A(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Fss_[static_cast<std::size_t>(i) * n + j] = vf_.F(i, j);
      A[static_cast<std::size_t>(i) * n + j] = (i == j ? 1.0 : 0.0) - rho_[i] * vf_.F(i, j);
    }
    Fsp_[i] = vf_.F(i, P);
  }
  inverse_ = dense_inverse(std::move(A), n);
}

BandSolution CavityEnclosure::solve(const std::vector<double>& emitted, const std::vector<double>& primary,
                                    double J_aperture) const {
  const int n = surfaces(), P = vf_.aperture();
  std::vector<double> b(n);
  for (int i = 0; i < n; ++i) b[i] = emitted[i] + rho_[i] * (primary[i] + Fsp_[i] * J_aperture);
  BandSolution s;
  s.J.assign(n, 0.0);
  s.H.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.J[i] += inverse_[static_cast<std::size_t>(i) * n + j] * b[j];
  for (int i = 0; i < n; ++i) {
    double h = Fsp_[i] * J_aperture;
    for (int j = 0; j < n; ++j) h += Fss_[static_cast<std::size_t>(i) * n + j] * s.J[j];
    s.H[i] = h;
    s.aperture_out += vf_.exchange(i, P) * s.J[i];
  }
  s.aperture_in = vf_.area[P] * J_aperture;
  return s;
}

void CavityEnclosure::irradiation_map(const std::vector<double>& eps, std::vector<double>& M,
                                      std::vector<double>& m) const {
  // J = inverse (eps E + rho Fsp E_env), H = Fss J + Fsp E_env.
  const int n = surfaces();
  std::vector<double> rf(n), inv_rf(n, 0.0);
  for (int i = 0; i < n; ++i) rf[i] = rho_[i] * Fsp_[i];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) inv_rf[i] += inverse_[static_cast<std::size_t>(i) * n + j] * rf[j];
  M.assign(static_cast<std::size_t>(n) * n, 0.0);
  m.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double* Mi = &M[static_cast<std::size_t>(i) * n];
    for (int k = 0; k < n; ++k) {
      const double f = Fss_[static_cast<std::size_t>(i) * n + k];
      if (f == 0.0) continue;
      const double* Bk = &inverse_[static_cast<std::size_t>(k) * n];
      for (int j = 0; j < n; ++j) Mi[j] += f * Bk[j];
      m[i] += f * inv_rf[k];
    }
    for (int j = 0; j < n; ++j) Mi[j] *= eps[j];
    m[i] += Fsp_[i];
  }
}

double apparent_emissivity(const CavityViewFactors& vf, double eps) {
  const int n = vf.size() - 1;
  CavityEnclosure e(vf, std::vector<double>(n, 1.0 - eps));
  const BandSolution s = e.solve(std::vector<double>(n, eps), std::vector<double>(n, 0.0), 0.0);
  return s.aperture_out / vf.area[vf.aperture()];
}

}  // namespace centrec::thermal
