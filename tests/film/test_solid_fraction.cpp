// Sphere-in-shell volumes and the solid fraction sampler on known lattices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dem/film/solid_fraction.hpp"
#include "dem/film/sphere_shell_volume.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double d = 1.2e-3, R = 50 * d;
double v_sphere(double a) { return 4.0 / 3.0 * M_PI * a * a * a; }
// Spherical cap of height h.
double cap(double a, double h) { return M_PI * h * h * (3 * a - h) / 3.0; }
}  // namespace

TEST(SphereShellVolume, FlatLimitAndAdditivity) {
  const double a = 0.5;
  // Far from the axis the cylinder is a plane: the part inside rho is a cap.
  const double c = 1e5;
  double worst = 0;
  for (double h : {0.05, 0.3, 0.5, 0.77, 0.99}) {
    const double v = sphere_in_cylinder_volume(c - a + h, a, c);
    worst = std::max(worst, std::fabs(v - cap(a, h)) / v_sphere(a));
  }
  // Shells tiling the sphere add up to it.
  double sum = 0;
  for (int k = 0; k < 7; ++k) sum += sphere_in_shell_volume(1.7 + 0.17 * k, 1.7 + 0.17 * (k + 1), a, 2.2);
  std::printf("flat limit: worst |V - cap| = %.2e of the sphere; 7 shells sum to %.12f of it\n", worst,
              sum / v_sphere(a));
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(sum / v_sphere(a), 1.0, 1e-9);
  EXPECT_EQ(sphere_in_cylinder_volume(10.0, a, 2.0), v_sphere(a));
  EXPECT_EQ(sphere_in_cylinder_volume(1.0, a, 2.0), 0.0);
}

TEST(SphereShellVolume, AgainstBruteForceSlicing) {
  // Reference: the same slice areas summed by the midpoint rule on 200000 slices, with no
  // stretch splitting or substitution; D/d = 100 (the paper's D12) and D/d = 5.
  double worst = 0;
  for (double c_over_a : {99.0, 4.0})
    for (double off : {-0.93, -0.5, -0.1, 0.0, 0.37, 0.81}) {
      const double a = 1.0, c = c_over_a * a, rho = c + off * a;
      const int n = 200000;
      double ref = 0;
      for (int i = 0; i < n; ++i) {
        const double zeta = -a + (i + 0.5) * 2 * a / n;
        ref += disk_in_circle_area(rho, std::sqrt(a * a - zeta * zeta), c) * 2 * a / n;
      }
      worst = std::max(worst, std::fabs(sphere_in_cylinder_volume(rho, a, c) - ref) / v_sphere(a));
    }
  std::printf("against brute-force slicing: worst difference %.2e of the sphere volume\n", worst);
  EXPECT_LT(worst, 1e-7);
}

TEST(SphereShellVolume, StrongCurvatureAgainstMonteCarlo) {
  // Sphere of radius 1 centred 1.5 from the axis, cylinder radius 1.2: a cut with
  // curvature comparable to the sphere's, far from the flat limit.
  const double a = 1.0, c = 1.5, rho = 1.2;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const long n = 4000000;
  long in_sphere = 0, in_both = 0;
  for (long i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    if (x * x + y * y + z * z > 1.0) continue;
    ++in_sphere;
    if ((x + c) * (x + c) + z * z < rho * rho) ++in_both;  // axis along y, centre at (c, 0, 0)
  }
  const double frac_mc = static_cast<double>(in_both) / in_sphere;
  const double sigma = std::sqrt(frac_mc * (1 - frac_mc) / in_sphere);
  const double frac = sphere_in_cylinder_volume(rho, a, c) / v_sphere(a);
  std::printf("curved cut: quadrature %.6f of the sphere, Monte Carlo %.6f +- %.6f\n", frac, frac_mc, sigma);
  EXPECT_NEAR(frac, frac_mc, 4 * sigma);
}

TEST(SolidFraction, CubicLatticeLayersAndZones) {
  // Cubic film: 4 layers of touching spheres at wall distances 0.5, 1.5, 2.5, 3.5 d.
  const double L = 10 * d;
  Particles p = layered_lattice(R, L, d, 4, d, d, d, false);
  const DrumFrame f = paper_view_frame(R, L);
  // Bins one diameter wide hold whole layers: phi = n V_p / V_shell exactly.
  SolidFractionConfig c;
  c.bins.particle_diameter = d;
  c.bins.width_d = 1.0;
  c.bins.count = 5;
  c.zone_of_bin = {0, 0, 0, 1, 1, 1};  // two zones, 180 deg each
  SolidFractionSampler s(f, c);
  s.add_snapshot(p.view());
  s.end_period();
  // Hand count per zone and layer.
  std::vector<std::vector<double>> n(2, std::vector<double>(5, 0.0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int layer = static_cast<int>((R - std::hypot(p.x[i], p.y[i])) / d);
    const int zone = f.theta(p.x[i], p.y[i]) < M_PI ? 0 : 1;
    n[zone][layer] += 1;
  }
  double worst = 0;
  for (int z = 0; z < 2; ++z) {
    const auto prof = s.profile(z);
    for (int k = 0; k < 5; ++k) {
      const double ro = R - k * d, ri = R - (k + 1) * d;
      const double expect = n[z][k] * v_sphere(d / 2) / (0.5 * M_PI * (ro * ro - ri * ri) * L);
      worst = std::max(worst, std::fabs(prof[k].mean - expect));
      if (z == 0) std::printf("layer bin %d-%d d: phi %.5f (hand count %.5f)\n", k, k + 1, prof[k].mean, expect);
    }
  }
  EXPECT_LT(worst, 1e-9);

  // Half-diameter bins split each sphere near its equator: the wall-side half holds
  // slightly more than half (the shell widens outward), each close to phi_layer.
  c.bins.width_d = 0.5;
  c.bins.count = 8;
  c.zone_of_bin = {0};
  SolidFractionSampler h(f, c);
  h.add_snapshot(p.view());
  h.end_period();
  const auto prof = h.profile(0);
  const double layer0 = s.profile(0)[0].mean;
  std::printf("half-d bins: %.4f %.4f %.4f %.4f (whole-layer bin %.4f)\n", prof[0].mean, prof[1].mean, prof[2].mean,
              prof[3].mean, layer0);
  EXPECT_NEAR(prof[0].mean, layer0, 0.02 * layer0);
  EXPECT_NEAR(prof[1].mean, layer0, 0.02 * layer0);
  // Volume conservation: the two half bins carry the whole layer.
  const double ro = R, rm = R - 0.5 * d, ri = R - d;
  const double v0 = prof[0].mean * (ro * ro - rm * rm), v1 = prof[1].mean * (rm * rm - ri * ri);
  EXPECT_NEAR((v0 + v1) / (layer0 * (ro * ro - ri * ri)), 1.0, 1e-9);
}
