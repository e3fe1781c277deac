// Full-circumference profiles per axial section (dem/film/ring_profile.hpp): on a known
// lattice the solid fraction equals the hand count, the profiles carry exactly the axial
// flow of the particles they cover (the property the coupling's flux closure relies on),
// the velocity is the mass-weighted mean, and sections split the drum by axial position.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "dem/film/ring_profile.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double d = 1.2e-3, R = 50 * d;
double v_sphere(double a) { return 4.0 / 3.0 * M_PI * a * a * a; }
double shell(const WallDistanceBins& b, int k, double length) {
  const double ro = R - b.lower_m(k), ri = R - b.upper_m(k);
  return M_PI * (ro * ro - ri * ri) * length;
}
}  // namespace

TEST(RingProfile, LatticeSolidFractionAndExactFlow) {
  const double L = 12 * d;
  Particles p = layered_lattice(R, L, d, 4, d, d, d, false);
  // Velocities: the wall layer at rest, the others faster with height and varying around
  // the drum (a moving and a slower zone), so the mass-weighted mean is not a plain mean.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-0.02, 0.02);
  p.vz.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = R - std::hypot(p.x[i], p.y[i]);
    p.vz[i] = w < d ? 0.0 : (0.1 * (w / d - 0.5) + noise(rng)) * (p.y[i] > 0 ? 1.0 : 0.3);
  }
  RingProfileConfig c;
  c.bins.particle_diameter = d;
  c.bins.width_d = 0.5;
  c.bins.count = 10;
  c.sections = 3;
  RingProfileSampler s(paper_view_frame(R, L), c);
  s.add_snapshot(p.view());
  s.end_period();

  // 1. Each section carries exactly the axial volume flow of its particles.
  double worst_flow = 0.0, worst_phi = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double z0 = a * L / 3, z1 = (a + 1) * L / 3;
    double direct = 0.0, vol = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.z[i] >= z0 && p.z[i] < z1) direct += v_sphere(p.radius[i]) * p.vz[i], vol += v_sphere(p.radius[i]);
    const auto flux = s.volume_flux(a), phi = s.solid_fraction(a);
    double from_bins = 0.0, vol_bins = 0.0;
    for (int k = 0; k < c.bins.count; ++k) {
      from_bins += flux[k].mean * shell(c.bins, k, L / 3);
      vol_bins += phi[k].mean * shell(c.bins, k, L / 3);
    }
    std::printf("section %d: volume flow from the bins %.9e m4/s vs particles %.9e; volume %.9e vs %.9e m3\n", a,
                from_bins, direct, vol_bins, vol);
    worst_flow = std::max(worst_flow, std::abs(from_bins / direct - 1.0));
    worst_phi = std::max(worst_phi, std::abs(vol_bins / vol - 1.0));
  }
  EXPECT_LT(worst_flow, 1e-12);
  EXPECT_LT(worst_phi, 1e-12);

  // 2. Solid fraction of whole-layer bins against a hand count (1 d bins hold whole layers).
  RingProfileConfig whole = c;
  whole.bins.width_d = 1.0;
  whole.bins.count = 5;
  whole.sections = 1;
  RingProfileSampler w(paper_view_frame(R, L), whole);
  w.add_snapshot(p.view());
  w.end_period();
  std::vector<double> n(5, 0.0), m(5, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int layer = static_cast<int>((R - std::hypot(p.x[i], p.y[i])) / d);
    n[layer] += 1;
    m[layer] += p.vz[i];
  }
  for (int k = 0; k < 4; ++k) {
    const double expect = n[k] * v_sphere(d / 2) / shell(whole.bins, k, L);
    const auto phi = w.solid_fraction(0)[k].mean, u = w.volume_flux(0)[k].mean / phi;
    std::printf("layer %d: phi %.6f (hand count %.6f), u %.6f m/s (mean of the layer %.6f)\n", k, phi, expect, u,
                m[k] / n[k]);
    EXPECT_NEAR(phi, expect, 1e-9);
    EXPECT_NEAR(u, m[k] / n[k], 1e-12);  // equal spheres: mass-weighted = plain mean
  }
  EXPECT_NEAR(w.solid_fraction(0)[4].mean, 0.0, 1e-15);
}

TEST(RingProfile, SpreadOverPeriodsAndCheckpoint) {
  const double L = 6 * d;
  Particles p = layered_lattice(R, L, d, 2, d, d, d, false);
  p.vz.assign(p.size(), 0.0);
  RingProfileConfig c;
  c.bins.particle_diameter = d;
  c.bins.count = 6;
  RingProfileSampler s(paper_view_frame(R, L), c);
  for (double v : {0.1, 0.3}) {  // two periods at different speeds
    for (double& x : p.vz) x = v;
    s.add_snapshot(p.view());
    s.end_period();
  }
  const auto q = s.volume_flux(0), phi = s.solid_fraction(0);
  EXPECT_NEAR(q[0].mean / phi[0].mean, 0.2, 1e-12);
  EXPECT_NEAR(q[0].stddev / phi[0].mean, std::sqrt(0.02), 1e-12);  // sample std of 0.1 and 0.3
  EXPECT_EQ(q[0].periods, 2u);
  PackedState st;
  s.save(st);
  RingProfileSampler t(paper_view_frame(R, L), c);
  StateReader in(st.data, "test");
  t.load(in);
  EXPECT_EQ(t.volume_flux(0)[0].mean, q[0].mean);
  EXPECT_EQ(t.solid_fraction(0)[1].stddev, phi[1].stddev);
}
