#include "cavity_view_factors.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::thermal {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double disc_to_disc_view_factor(double r1, double r2, double h) {
  const double c = (r2 * r2) / (r1 * r1);
  const double X = 1.0 + (h * h + r2 * r2) / (r1 * r1);
  // X^2 - 4c = (X - 2 sqrt c)(X + 2 sqrt c) = ((r1 - r2)^2 + h^2)((r1 + r2)^2 + h^2) / r1^4,
  // free of cancellation for thin rings (h -> 0).
  const double r14 = r1 * r1 * r1 * r1;
  const double disc = ((r1 - r2) * (r1 - r2) + h * h) * ((r1 + r2) * (r1 + r2) + h * h) / r14;
  return 2.0 * c / (X + std::sqrt(disc));
}

double ring_element_to_end_disc(double R, double h) {
  const double H = h / R;
  return 0.5 * ((H * H + 2.0) / std::sqrt(H * H + 4.0) - H);
}

double ring_element_to_coaxial_disc(double R, double r, double h) {
  const double H = h / R, P = r / R, X = 1.0 + H * H + P * P;
  return 0.5 * H * (X / std::sqrt(X * X - 4.0 * P * P) - 1.0);
}

CavityViewFactors cavity_view_factors(double R, const std::vector<double>& z, double ra) {
  if (!(R > 0)) throw std::invalid_argument("cavity view factors: the radius must be > 0");
  if (z.size() < 2 || z.front() != 0.0) throw std::invalid_argument("cavity view factors: ring boundaries must start at z = 0");
  for (std::size_t k = 1; k < z.size(); ++k)
    if (!(z[k] > z[k - 1])) throw std::invalid_argument("cavity view factors: ring boundaries must increase");
  if (!(ra > 0 && ra <= R * (1 + 1e-12))) throw std::invalid_argument("cavity view factors: the aperture radius must be in (0, R]");
  ra = std::min(ra, R);
  CavityViewFactors v;
  v.n_rings = static_cast<int>(z.size()) - 1;
  v.front_annulus = ra < R * (1 - 1e-12);
  const int n = v.n_rings;
  const double L = z.back(), AD = kPi * R * R, AP = kPi * ra * ra;
  for (int i = 0; i < n; ++i) v.area.push_back(2.0 * kPi * R * (z[i + 1] - z[i]));
  v.area.push_back(AD);                        // back disc
  if (v.front_annulus) v.area.push_back(AD - AP);  // front annulus
  v.area.push_back(AP);                        // aperture
  const int N = v.size();
  v.S.assign(static_cast<std::size_t>(N) * N, 0.0);
  auto set = [&](int i, int j, double s) {
    v.S[static_cast<std::size_t>(i) * N + j] = s;
    v.S[static_cast<std::size_t>(j) * N + i] = s;
  };
  auto f = [&](double h) { return disc_to_disc_view_factor(R, R, h); };   // virtual disc to virtual disc
  auto g = [&](double h) { return disc_to_disc_view_factor(ra, R, h); };  // aperture to virtual disc
  const int B = v.back(), A = v.annulus(), P = v.aperture();
  for (int i = 0; i < n; ++i) {
    const double a = z[i], b = z[i + 1];
    set(i, i, v.area[i] - 2.0 * AD * (1.0 - f(b - a)));
    for (int j = i + 1; j < n; ++j) {
      const double c = z[j], d = z[j + 1];
      set(i, j, AD * (f(c - b) - f(c - a) - f(d - b) + f(d - a)));
    }
    set(i, B, AD * (f(a) - f(b)));
    const double to_aperture = AP * (g(L - b) - g(L - a));
    set(i, P, to_aperture);
    if (A >= 0) set(i, A, AD * (f(L - b) - f(L - a)) - to_aperture);
  }
  set(B, P, AP * g(L));
  if (A >= 0) set(B, A, AD * f(L) - AP * g(L));
  return v;
}

}  // namespace centrec::thermal
