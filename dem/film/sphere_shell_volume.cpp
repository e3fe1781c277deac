#include "sphere_shell_volume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace centrec::film {

namespace {
constexpr int kGauss = 12;

// Gauss-Legendre nodes and weights on [-1, 1], by Newton iteration on P_n.
struct GaussLegendre {
  std::array<double, kGauss> x{}, w{};
  GaussLegendre() {
    const int n = kGauss;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(M_PI * (i + 0.75) / (n + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::fabs(dz) < 1e-15) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

const GaussLegendre& gauss() {
  static const GaussLegendre g;
  return g;
}
}  // namespace

namespace {
// Area of the segment of a circle of radius r cut off by a chord at height h (0..2r)
// from the rim: r^2/2 (x - sin x) with x = 2 alpha, alpha = 2 asin(sqrt(h / 2r)) the half
// angle. Written so that a thin segment of a huge circle (the drum wall against a
// particle, D/d up to thousands) keeps full precision: no acos near 1, a series for x - sin x.
double segment_area(double r, double h) {
  h = std::clamp(h, 0.0, 2.0 * r);
  const double x = 4.0 * std::asin(std::sqrt(h / (2.0 * r)));
  const double x2 = x * x;
  const double x_minus_sin = x < 1e-2 ? x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0)) : x - std::sin(x);
  return 0.5 * r * r * x_minus_sin;
}
}  // namespace

double disk_in_circle_area(double rho, double s, double c) {
  if (s <= 0.0 || rho <= 0.0) return 0.0;
  if (c >= rho + s) return 0.0;                                // apart
  if (c <= std::fabs(rho - s)) return M_PI * std::min(rho, s) * std::min(rho, s);  // one inside the other
  // Lens = segment of the circle beyond the common chord + segment of the disk before it.
  // Heights from the chord, in factored form (no cancellation of large squares):
  const double h_circle = (s - (c - rho)) * (s + (c - rho)) / (2.0 * c);
  const double h_disk = (rho - c + s) * (rho + c - s) / (2.0 * c);
  return segment_area(rho, h_circle) + segment_area(s, h_disk);
}

double sphere_in_cylinder_volume(double rho, double a, double c) {
  const double v_sphere = 4.0 / 3.0 * M_PI * a * a * a;
  if (rho <= 0.0) return 0.0;
  if (c + a <= rho) return v_sphere;
  if (c - a >= rho) return 0.0;
  // Breakpoints in zeta in [0, a]: the slice radius s equals |rho - c| or rho + c.
  std::array<double, 4> cut{0.0, a, a, a};
  int nc = 1;
  for (double b : {std::fabs(rho - c), rho + c})
    if (b < a) cut[nc++] = std::sqrt(a * a - b * b);
  cut[nc++] = a;
  for (int i = 1; i < nc; ++i)  // insertion sort of at most four values
    for (int j = i; j > 0 && cut[j] < cut[j - 1]; --j) std::swap(cut[j], cut[j - 1]);
  const GaussLegendre& g = gauss();
  double v = 0.0;
  for (int k = 0; k + 1 < nc; ++k) {
    const double lo = cut[k], hi = cut[k + 1];
    if (hi <= lo) continue;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    // A stretch where the slices lie wholly inside (area pi s^2) or outside (0) the
    // circle integrates in closed form: pi (a^2 zeta - zeta^3 / 3).
    const double s_mid = std::sqrt(std::max(0.0, a * a - mid * mid));
    if (s_mid <= std::fabs(rho - c) || c >= rho + s_mid) {
      if (c < rho) v += M_PI * (a * a * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
      continue;
    }
    // Straddling stretch: the lens area starts like (zeta_k - zeta)^(3/2) at a tangency.
    // zeta = mid + half sin(pi u / 2) clusters the nodes at both ends and makes the
    // integrand smooth in u, so 12 Gauss points reach ~1e-8 of the sphere.
    for (int i = 0; i < kGauss; ++i) {
      const double ang = 0.5 * M_PI * g.x[i];
      const double zeta = mid + half * std::sin(ang);
      const double jac = half * 0.5 * M_PI * std::cos(ang);
      v += g.w[i] * jac * disk_in_circle_area(rho, std::sqrt(std::max(0.0, a * a - zeta * zeta)), c);
    }
  }
  return 2.0 * v;  // the sphere is symmetric in zeta
}

double sphere_in_shell_volume(double r_in, double r_out, double a, double c) {
  if (r_out <= r_in) return 0.0;
  return sphere_in_cylinder_volume(r_out, a, c) - sphere_in_cylinder_volume(r_in, a, c);
}

}  // namespace centrec::film
