// Radiosity enclosure of the receiver cavity: an isothermal closed cavity exchanges
// nothing; the apparent emissivity of an isothermal cylindrical cavity with an aperture
// against an independent Monte Carlo ray trace of the same cavity (diffuse grey walls);
// band solutions conserve energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "thermal/cavity_radiation.hpp"

using namespace centrec::thermal;

namespace {
constexpr double kPi = 3.14159265358979323846;

std::vector<double> uniform_rings(double L, int n) {
  std::vector<double> z(n + 1);
  for (int k = 0; k <= n; ++k) z[k] = L * k / n;
  z[n] = L;
  return z;
}

// Monte Carlo absorptance of an isothermal diffuse grey cylindrical cavity (radius R,
// length L, back disc at z = 0, front plane z = L with an aperture of radius ra): rays
// enter through the aperture with a cosine distribution; at each wall hit the weight
// loses the fraction eps (absorbed) and the rest is reflected diffusely. By Kirchhoff's
// law this absorptance equals the apparent emissivity. Independent of the view factors.
double monte_carlo_apparent_emissivity(double R, double L, double ra, double eps, int rays, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double absorbed = 0.0;
  auto cosine_dir = [&](const double n[3], double d[3]) {
    // Cosine-weighted direction about the unit normal n.
    const double u1 = U(rng), u2 = U(rng);
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    const double lx = r * std::cos(phi), ly = r * std::sin(phi), lz = std::sqrt(std::max(0.0, 1 - u1));
    double t1[3];
    if (std::abs(n[0]) < 0.9) {
      t1[0] = 0; t1[1] = -n[2]; t1[2] = n[1];  // n x e_x
    } else {
      t1[0] = n[2]; t1[1] = 0; t1[2] = -n[0];  // n x e_y
    }
    const double tn = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (double& x : t1) x /= tn;
    const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
    for (int k = 0; k < 3; ++k) d[k] = lx * t1[k] + ly * t2[k] + lz * n[k];
  };
  for (int ray = 0; ray < rays; ++ray) {
    // Start on the aperture disc (uniform in area), heading into the cavity (-z).
    const double rr = ra * std::sqrt(U(rng)), ph = 2 * kPi * U(rng);
    double p[3] = {rr * std::cos(ph), rr * std::sin(ph), L}, d[3];
    const double n0[3] = {0, 0, -1};
    cosine_dir(n0, d);
    double w = 1.0;
    while (w > 1e-9) {
      // Distance to the cylinder wall (x^2 + y^2 = R^2, moving outwards) and to the planes.
      const double a = d[0] * d[0] + d[1] * d[1], b = p[0] * d[0] + p[1] * d[1], c = p[0] * p[0] + p[1] * p[1] - R * R;
      double t_cyl = INFINITY;
      if (a > 0) t_cyl = (-b + std::sqrt(std::max(0.0, b * b - a * c))) / a;
      const double t_back = d[2] < 0 ? -p[2] / d[2] : INFINITY;
      const double t_front = d[2] > 0 ? (L - p[2]) / d[2] : INFINITY;
      double n[3];
      if (t_cyl <= t_back && t_cyl <= t_front) {
        for (int k = 0; k < 3; ++k) p[k] += t_cyl * d[k];
        const double r = std::sqrt(p[0] * p[0] + p[1] * p[1]);
        n[0] = -p[0] / r; n[1] = -p[1] / r; n[2] = 0;
      } else if (t_back <= t_front) {
        for (int k = 0; k < 3; ++k) p[k] += t_back * d[k];
        p[2] = 0.0;
        n[0] = 0; n[1] = 0; n[2] = 1;
      } else {
        for (int k = 0; k < 3; ++k) p[k] += t_front * d[k];
        p[2] = L;
        if (p[0] * p[0] + p[1] * p[1] < ra * ra) break;  // escaped through the aperture
        n[0] = 0; n[1] = 0; n[2] = -1;
      }
      absorbed += w * eps;
      w *= 1.0 - eps;
      cosine_dir(n, d);
    }
  }
  return absorbed / rays;
}
}  // namespace

TEST(CavityRadiation, IsothermalClosedCavityHasNoNetExchange) {
  // Closed cavity: the "aperture" radiates as a black surface at the cavity temperature.
  const CavityViewFactors v = cavity_view_factors(0.5, uniform_rings(1.4, 40), 0.35);
  const int n = v.size() - 1;
  std::vector<double> eps(n, 0.86);
  eps[v.back()] = 0.6;
  eps[v.annulus()] = 0.4;
  std::vector<double> rho(n);
  for (int i = 0; i < n; ++i) rho[i] = 1.0 - eps[i];
  const CavityEnclosure enc(v, rho);
  const double E = 5.670374419e-8 * std::pow(1200.0, 4);
  std::vector<double> e(n);
  for (int i = 0; i < n; ++i) e[i] = eps[i] * E;
  const BandSolution s = enc.solve(e, std::vector<double>(n, 0.0), E);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(eps[i] * (E - s.H[i])) / E);
  std::vector<double> M, m;
  enc.irradiation_map(eps, M, m);
  double map_err = 0.0;
  for (int i = 0; i < n; ++i) {
    double row = m[i];
    for (int j = 0; j < n; ++j) row += M[static_cast<std::size_t>(i) * n + j];
    map_err = std::max(map_err, std::abs(row - 1.0));
  }
  const double net_aperture = (s.aperture_out - s.aperture_in) / (v.area[v.aperture()] * E);
  std::printf("isothermal 1200 K: max |net flux| / sigma T^4 = %.2e, irradiation map |M 1 + m - 1| = %.2e, net through "
              "the aperture %.2e (tolerance 1e-12)\n",
              worst, map_err, net_aperture);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(map_err, 1e-12);
  EXPECT_LT(std::abs(net_aperture), 1e-12);
}

TEST(CavityRadiation, ApparentEmissivityMatchesMonteCarloWithin1Percent) {
  struct Case {
    double R, L, ra, eps;
  };
  const Case cases[] = {{1.0, 2.0, 1.0, 0.5}, {1.0, 4.0, 1.0, 0.5}, {1.0, 2.0, 0.5, 0.75}, {1.0, 1.0, 1.0, 0.86}};
  for (const Case& c : cases) {
    const double ea = apparent_emissivity(cavity_view_factors(c.R, uniform_rings(c.L, 200), c.ra), c.eps);
    const double ea50 = apparent_emissivity(cavity_view_factors(c.R, uniform_rings(c.L, 50), c.ra), c.eps);
    const double mc = monte_carlo_apparent_emissivity(c.R, c.L, c.ra, c.eps, 400000, 12345);
    // Gouffe's estimate (isothermal cavity, uniform irradiation): eps / (eps + (1 - eps) A_ap / A_cav).
    const double Acav = 2 * kPi * c.R * c.L + kPi * c.R * c.R + kPi * (c.R * c.R - c.ra * c.ra);
    const double gouffe = c.eps / (c.eps + (1 - c.eps) * kPi * c.ra * c.ra / Acav);
    std::printf("L/R %.1f, r_a/R %.2f, eps %.2f: apparent emissivity %.5f (200 rings), %.5f (50 rings); Monte Carlo "
                "%.5f (4e5 rays); Gouffe estimate %.5f; difference to Monte Carlo %.3f %% (tolerance 1 %%)\n",
                c.L / c.R, c.ra / c.R, c.eps, ea, ea50, mc, gouffe, 100 * (ea / mc - 1));
    EXPECT_LT(std::abs(ea / mc - 1.0), 0.01);
    EXPECT_GT(ea, c.eps);  // the cavity is blacker than its walls
  }
}

TEST(CavityRadiation, SolarBandConservesEnergy) {
  // Collimated sunlight on the rings: absorbed + leaving through the aperture = incident.
  const CavityViewFactors v = cavity_view_factors(0.5, uniform_rings(1.0, 30), 0.3);
  const int n = v.size() - 1;
  std::vector<double> rho(n, 0.08), primary(n, 0.0);
  rho[v.back()] = 0.7;
  rho[v.annulus()] = 0.7;
  double incident = 0.0;
  for (int i = 0; i < v.n_rings; ++i) {
    primary[i] = 1e6 * (1.0 + 0.5 * i / v.n_rings);
    incident += primary[i] * v.area[i];
  }
  const CavityEnclosure enc(v, rho);
  const BandSolution s = enc.solve(std::vector<double>(n, 0.0), primary, 0.0);
  double absorbed = 0.0;
  for (int i = 0; i < n; ++i) absorbed += (1 - rho[i]) * (primary[i] + s.H[i]) * v.area[i];
  const double reflected_once = 0.08;  // film reflectance: an open surface would lose it all
  std::printf("solar band: incident %.6g W, absorbed %.6g W, out through the aperture %.6g W (%.3f %% of incident; "
              "an open film would lose %.1f %%), balance %.2e\n",
              incident, absorbed, s.aperture_out, 100 * s.aperture_out / incident, 100 * reflected_once,
              (incident - absorbed - s.aperture_out) / incident);
  EXPECT_LT(std::abs(incident - absorbed - s.aperture_out) / incident, 1e-13);
  EXPECT_LT(s.aperture_out, reflected_once * incident);  // the cavity re-absorbs reflected light
}
