// Where the film absorbs the sunlight (thermal/solar_extinction.hpp):
//   - on a uniform film the local form equals the column-mean Beer-Lambert form (1e-12);
//   - against an independent Monte Carlo ray trace (written here, the test tool): black
//     spheres of diameter d placed by random sequential addition in a laterally periodic box
//     in three layers (phi about 0.30 near the wall, 0.15, 0.06 at the top: a loose top like
//     the DEM film's), rays straight down from above, each absorbed by the first sphere it
//     meets, whose volume then holds that power (a near-isothermal particle: what the
//     continuum's cells receive). The packing's exact solid fraction per 0.25 d bin
//     (sphere-slab volumes) is handed to the model; the depth distribution of the absorbed
//     power must agree within 5 % of the absorbed power (half the L1 distance of the two
//     distributions; 2e5 rays, statistical error about 0.5 %). The column-mean form and the
//     point-scattering coefficient 1.5 phi / d on the same packing are printed for
//     comparison, and the column-mean form must be the worse one (with the depth of a bed of
//     the mean phi it stops the light within the loose top, which the rays mostly pass).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "thermal/solar_extinction.hpp"

using namespace centrec::thermal;

namespace {
constexpr double kPi = 3.14159265358979323846;

struct Sphere {
  double x, y, z;
};

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

// Minimum-image lateral distance squared in a periodic box of side L.
double lateral2(double dx, double dy, double L) {
  dx -= L * std::round(dx / L);
  dy -= L * std::round(dy / L);
  return dx * dx + dy * dy;
}

// Volume of a sphere (centre zc, radius r) between the planes z = a and z = b.
double slab_volume(double zc, double r, double a, double b) {
  const double lo = std::max(a, zc - r) - zc, hi = std::min(b, zc + r) - zc;
  if (!(hi > lo)) return 0.0;
  return kPi * (r * r * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
}

double half_l1(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) s += std::abs(a[j] - b[j]);
  return 0.5 * s;
}
}  // namespace

TEST(SolarExtinction, LocalEqualsColumnMeanOnAUniformFilm) {
  const double d = 1.2e-3, phi = 0.55, t = 6e-3;
  const int n = 40;
  const double deta = t / n, dl = extinction_depth_d_from_phi(phi) * d;
  const std::vector<double> s = local_extinction_shares(std::vector<double>(n, phi), deta, d);
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {
    const double lo = j * deta, hi = (j + 1) * deta;
    const double column = std::exp(-(t - hi) / dl) * -std::expm1(-(hi - lo) / dl) / -std::expm1(-t / dl);
    worst = std::max(worst, std::abs(s[j] - column));
  }
  std::printf("uniform phi 0.55: worst |local - column-mean share| %.2e (tolerance 1e-12); depth %.3f d\n", worst,
              extinction_depth_d_from_phi(phi));
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(extinction_depth_d_from_phi(0.55), 0.5454545454545454, 1e-15);
}

TEST(SolarExtinction, LocalDepthMatchesARayTraceThroughARandomPacking) {
  const double d = 1.0, r = 0.5 * d, L = 12.0 * d;
  std::mt19937_64 g(20261204);
  std::vector<Sphere> spheres;
  // Three layers of centres (from the wall up) and their target solid fractions.
  const struct { double zlo, zhi, phi; } layers[] = {{0.5, 2.5, 0.30}, {2.5, 4.5, 0.15}, {4.5, 6.0, 0.06}};
  const double v_sphere = kPi * d * d * d / 6.0;
  for (const auto& ly : layers) {
    const int target = static_cast<int>(std::lround(ly.phi * L * L * (ly.zhi - ly.zlo) / v_sphere));
    int placed = 0;
    for (long attempt = 0; placed < target && attempt < 2000000; ++attempt) {
      const Sphere c{unit(g) * L, unit(g) * L, ly.zlo + unit(g) * (ly.zhi - ly.zlo)};
      bool free = true;
      for (const Sphere& o : spheres)
        if (lateral2(c.x - o.x, c.y - o.y, L) + (c.z - o.z) * (c.z - o.z) < d * d) {
          free = false;
          break;
        }
      if (free) {
        spheres.push_back(c);
        ++placed;
      }
    }
    ASSERT_EQ(placed, target) << "random sequential addition did not reach phi " << ly.phi;
  }
  // The packing's solid fraction in bins of 0.25 d from the wall to the top of the top layer.
  const double t = 6.5 * d, deta = 0.25 * d;
  const int nb = static_cast<int>(std::lround(t / deta));
  std::vector<double> phi(nb, 0.0);
  for (int j = 0; j < nb; ++j) {
    for (const Sphere& s : spheres) phi[j] += slab_volume(s.z, r, j * deta, (j + 1) * deta);
    phi[j] /= L * L * deta;
  }
  // Rays straight down at random (x, y); absorbed at the first sphere surface they meet.
  const long rays = 200000;
  std::vector<double> hits(nb, 0.0);
  long absorbed = 0;
  for (long k = 0; k < rays; ++k) {
    const double x = unit(g) * L, y = unit(g) * L;
    double z_hit = -1.0;
    long hit = -1;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
      const Sphere& s = spheres[i];
      const double rho2 = lateral2(x - s.x, y - s.y, L);
      if (rho2 < r * r && s.z + std::sqrt(r * r - rho2) > z_hit) {
        z_hit = s.z + std::sqrt(r * r - rho2);
        hit = static_cast<long>(i);
      }
    }
    if (hit < 0) continue;  // reached the wall: the model renormalises over the film, so does this
    ++absorbed;
    // The particle takes the ray's power and holds it in its volume (a mm bauxite particle
    // is near isothermal: Biot number well below 1), so the continuum's absorbed power per
    // bin is the absorbing particles' volume in that bin.
    for (int j = 0; j < nb; ++j) hits[j] += slab_volume(spheres[hit].z, r, j * deta, (j + 1) * deta) / v_sphere;
  }
  for (double& h : hits) h /= static_cast<double>(absorbed);

  const std::vector<double> local = local_extinction_shares(phi, deta, d);
  // The same packing with one depth from the column's mean phi, and with the point-scattering
  // coefficient 1.5 phi / d (scale (1 - phi) per cell: not expressible as one scale, so by hand).
  double mean_phi = 0.0;
  for (double p : phi) mean_phi += p / nb;
  const std::vector<double> column = local_extinction_shares(std::vector<double>(nb, mean_phi), deta, d);
  std::vector<double> point(nb);
  {
    double tau = 0.0;
    for (int j = nb; j-- > 0;) {
      const double dtau = 1.5 * phi[j] * deta / d;
      point[j] = std::exp(-tau) * -std::expm1(-dtau);
      tau += dtau;
    }
    for (double& p : point) p /= -std::expm1(-tau);
  }
  std::printf("%zu spheres, %ld of %ld rays absorbed in the film; phi per 0.25 d bin from the top:", spheres.size(),
              absorbed, rays);
  for (int j = nb; j-- > nb - 12;) std::printf(" %.3f", phi[j]);
  std::printf(" ...\nbin from the top | ray trace | local Brewster | column mean | local point scattering\n");
  for (int j = nb; j-- > nb - 12;)
    std::printf("  %2d | %.4f | %.4f | %.4f | %.4f\n", nb - 1 - j, hits[j], local[j], column[j], point[j]);
  const double e_local = half_l1(hits, local), e_column = half_l1(hits, column), e_point = half_l1(hits, point);
  std::printf("misplaced share of the absorbed power against the ray trace: local %.4f (tolerance 0.05), column mean "
              "%.4f, local point scattering %.4f\n",
              e_local, e_column, e_point);
  EXPECT_LT(e_local, 0.05);
  EXPECT_GT(e_column, e_local);
}

// In the film operator: on a uniform film `extinction_local` gives the column-mean answer
// (T_out 1e-8 K); on a film with a loose top (phi 0.55 up to 0.6 t, then down to 0.1 at the
// surface) the light passes through the loose top into the denser bed below, as the ray
// trace above finds, instead of stopping within a mean-phi depth of the surface: the surface
// runs cooler, emits less and the efficiency rises; the receiver balance still closes to
// round-off (1e-10 of the aperture power).
#include <algorithm>

#include "film_test_cases.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

TEST(SolarExtinction, OperatorTakesTheLocalDepth) {
  namespace tc = centrec::thermal::testcases;
  FilmModel m = tc::cavity_model_q300k();
  FilmGridSpec g;
  g.nz = 30;
  g.nxi = 24;
  auto solve = [&](const FilmField& f, bool local) {
    FilmModel x = m;
    x.surface.extinction_local = local;
    FilmOperator op(f, x, g);
    op.freeze_inputs(true);
    const SteadyResult s = solve_steady(op, op.uniform_state(x.T_in), SteadySettings{});
    const FilmBalance b = op.balance(0.0, s.y.data());
    const ThermalFields fl = op.fields(0.0, s.y.data());
    return std::make_pair(b, *std::max_element(fl.T_surface.begin(), fl.T_surface.end()));
  };
  const FilmField uniform = tc::plug_film(6e-3, 0.05, 0.55, 1.0, 1.0);
  const auto u_col = solve(uniform, false), u_loc = solve(uniform, true);
  std::printf("uniform film: T_out column mean %.10f K, local %.10f K\n", u_col.first.T_out, u_loc.first.T_out);
  EXPECT_NEAR(u_col.first.T_out, u_loc.first.T_out, 1e-8);
  const FilmField loose = tc::loose_top_film();
  const auto l_col = solve(loose, false), l_loc = solve(loose, true);
  std::printf("loose top: max surface T column mean %.2f K, local %.2f K; efficiency %.5f, %.5f; receiver residual "
              "%.2e of aperture power\n",
              l_col.second, l_loc.second, l_col.first.efficiency, l_loc.first.efficiency,
              l_loc.first.receiver_residual / l_loc.first.aperture_power);
  EXPECT_LT(l_loc.second, l_col.second - 1.0);
  EXPECT_GT(l_loc.first.efficiency, l_col.first.efficiency);
  EXPECT_LT(std::abs(l_loc.first.receiver_residual / l_loc.first.aperture_power), 1e-10);
}
