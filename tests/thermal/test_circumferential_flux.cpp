// Flux around the circumference (docs/cavity_model.md): the surface ripple of periodic
// heating against a Crank-Nicolson finite-volume solution of the semi-infinite solid, and the
// mean excess of T^4 against quadrature over one period; then the quickstart's figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "thermal/circumferential_flux.hpp"
#include "thermal/physical_constants.hpp"

using namespace centrec::thermal;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Surface temperature amplitude over the last of `periods` periods of a slab of 12
// penetration depths (adiabatic at the bottom), flux q_a cos(omega t) at the top.
double numerical_ripple(double q_a, double k, double rho_c, double omega, int periods) {
  const double delta = std::sqrt(2.0 * k / (rho_c * omega));
  const int n = 480;
  const double dx = 12.0 * delta / n, a = k / (rho_c * dx * dx);
  const int steps = 2000;
  const double dt = 2.0 * kPi / omega / steps;
  std::vector<double> T(n, 0.0), lo(n), di(n), up(n), r(n);
  double tmax = -1e300, tmin = 1e300;
  for (int s = 0; s < periods * steps; ++s) {
    const double t0 = s * dt, t1 = t0 + dt;
    const double q = 0.5 * (std::cos(omega * t0) + std::cos(omega * t1)) * q_a;  // trapezoid of the flux
    // Cell 0 at the surface; Crank-Nicolson: (I - dt/2 L) T1 = (I + dt/2 L) T0 + dt q / (rho_c dx).
    for (int i = 0; i < n; ++i) {
      const double w = i > 0 ? a : 0.0, e = i + 1 < n ? a : 0.0;
      const double lap = (i > 0 ? w * (T[i - 1] - T[i]) : 0.0) + (i + 1 < n ? e * (T[i + 1] - T[i]) : 0.0);
      r[i] = T[i] + 0.5 * dt * lap + (i == 0 ? dt * q / (rho_c * dx) : 0.0);
      lo[i] = -0.5 * dt * w;
      up[i] = -0.5 * dt * e;
      di[i] = 1.0 + 0.5 * dt * (w + e);
    }
    for (int i = 1; i < n; ++i) {  // Thomas algorithm
      const double m = lo[i] / di[i - 1];
      di[i] -= m * up[i - 1];
      r[i] -= m * r[i - 1];
    }
    T[n - 1] = r[n - 1] / di[n - 1];
    for (int i = n - 2; i >= 0; --i) T[i] = (r[i] - up[i] * T[i + 1]) / di[i];
    if (s >= (periods - 1) * steps) {
      // Surface value: half a cell above the first centre, with the flux at t1.
      const double Ts = T[0] + q_a * std::cos(omega * t1) * 0.5 * dx / k;
      tmax = std::max(tmax, Ts);
      tmin = std::min(tmin, Ts);
    }
  }
  return 0.5 * (tmax - tmin);
}
}  // namespace

TEST(CircumferentialFlux, SurfaceRippleMatchesPeriodicConduction) {
  // The quickstart's film: k 0.9 W/(m K) (its k_eff), rho_s phi c_p = 3300 x 0.55 x 1200
  // J/(m3 K), 160.08 rpm; a cos profile of +-50 % of 200 kW/m2 on the film, alpha 0.92.
  const double k = 0.9, rho_c = 3300.0 * 0.55 * 1200.0, omega = 160.08 * 2 * kPi / 60, q_a = 0.5 * 0.92 * 2.0e5;
  const double theory = surface_ripple_amplitude(q_a, k, rho_c, omega);
  const double numeric = numerical_ripple(q_a, k, rho_c, omega, 8);
  std::printf("surface ripple: Carslaw & Jaeger %.4f K, Crank-Nicolson %.4f K (relative %.2e, tolerance 1e-2)\n", theory,
              numeric, numeric / theory - 1);
  EXPECT_NEAR(numeric / theory, 1.0, 1e-2);
  // Twice the speed: the ripple falls as omega^-1/2.
  EXPECT_NEAR(surface_ripple_amplitude(q_a, k, rho_c, 2 * omega) / theory, 1 / std::sqrt(2.0), 1e-14);
}

TEST(CircumferentialFlux, MeanEmissionExcessMatchesQuadrature) {
  const double T = 1150.0, theta = 40.0;
  const int n = 100000;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {  // the midpoint rule is exact to round-off for a trigonometric polynomial
    const double x = T + theta * std::cos(2 * kPi * (i + 0.5) / n);
    s += x * x * x * x - T * T * T * T;
  }
  const double quad = s / n, closed = ripple_t4_excess(T, theta);
  std::printf("mean T^4 excess at T 1150 K, ripple 40 K: closed form %.8e, quadrature %.8e K^4\n", closed, quad);
  EXPECT_NEAR(quad / closed, 1.0, 1e-9);
  // The quickstart's figure: the excess emission eps sigma <T^4 - T_mean^4> against the
  // absorbed flux, for the ripple of the test above.
  const double k = 0.9, rho_c = 3300.0 * 0.55 * 1200.0, omega = 160.08 * 2 * kPi / 60, q_a = 0.5 * 0.92 * 2.0e5;
  const double ripple = surface_ripple_amplitude(q_a, k, rho_c, omega);
  const double excess = 0.86 * kStefanBoltzmann * ripple_t4_excess(T, ripple);
  std::printf("quickstart, +-50 %% cos profile at 160 rpm: ripple %.2f K, extra emission %.1f W/m2 = %.3f %% of the "
              "absorbed 184 kW/m2\n", ripple, excess, 100 * excess / (0.92 * 2.0e5));
  EXPECT_LT(excess / (0.92 * 2.0e5), 1e-2);
}
