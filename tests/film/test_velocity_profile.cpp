// The arc-section velocity profile sampler on a synthetic shear field of known slope.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "dem/film/profile_fit.hpp"
#include "dem/film/velocity_profile.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double d = 1.2e-3, R = 50 * d, L = 142.5 * d;
// Slope of the synthetic field, 1/s, varying linearly with theta and z so a sampler that
// mixes up its sections reads the wrong slope.
double gamma_of(double theta, double z) { return 20.0 * (1.0 + 0.3 * theta / M_PI + 0.5 * z / L); }
}  // namespace

TEST(VelocityProfile, RecoversLinearShearInTheNineSections) {
  const DrumFrame f = paper_view_frame(R, L);
  VelocityProfileConfig c;
  c.bins.particle_diameter = d;
  c.bins.width_d = 0.5;
  c.bins.count = 14;
  VelocityProfileSampler s(f, c);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  const int periods = 6;
  std::size_t expected_in_s0 = 0;
  for (int per = 0; per < periods; ++per) {
    for (int snap = 0; snap < 2; ++snap) {
      Particles p;
      for (int i = 0; i < 150000; ++i) {
        const double w = (0.5 + 6.0 * u(rng)) * d, th = 2 * M_PI * u(rng), z = L * u(rng);
        p.add((R - w) * std::cos(th), (R - w) * std::sin(th), z, d / 2);
        // u = 0 in the wall layer (centres below 1 d), linear above (paper Fig 6).
        p.vz.back() = (w > d ? gamma_of(th, z) * (w - d) : 0.0) + noise(rng);
        const ArcSection& a = c.sections[0];
        if (std::fabs(z - a.z_over_length * L) <= c.axial_half_length * L && std::fabs(th - a.theta) <= c.arc_half_width)
          ++expected_in_s0;
      }
      s.add_snapshot(p.view());
    }
    s.end_period();
  }
  EXPECT_EQ(s.periods(), static_cast<std::size_t>(periods));
  std::size_t counted = 0;
  for (const ProfileBin& b : s.profile(0)) counted += b.samples;
  EXPECT_EQ(counted, expected_in_s0);

  for (std::size_t k = 0; k < c.sections.size(); ++k) {
    const ArcSection& a = c.sections[k];
    const auto prof = s.profile(static_cast<int>(k));
    // Fit in m/s per d between 1 d and 4 d, as the paper does for its Fig 6(a).
    const LineFit fit = fit_profile(prof, c.bins.width_d, 1.0, 4.0);
    const double expect = gamma_of(a.theta, a.z_over_length * L) * d;
    std::printf("section theta=%3.0f deg z/L=%.1f: slope %.5f m/s per d (true %.5f, %+.2f %%), wall-layer bin (0.5-1 d) u=%+.4f m/s "
                "(std over %zu turns %.4f), %zu samples in bin 3\n",
                a.theta * 180 / M_PI, a.z_over_length, fit.slope, expect, 100 * (fit.slope / expect - 1), prof[1].mean,
                prof[1].periods, prof[1].stddev, prof[3].samples);
    EXPECT_NEAR(fit.slope / expect, 1.0, 0.02) << k;
    EXPECT_NEAR(fit.intercept + fit.slope * 1.0, 0.0, 0.05 * expect);  // u(1 d) = 0
    EXPECT_NEAR(prof[1].mean, 0.0, 0.003);
    EXPECT_EQ(prof[0].samples, 0u);  // no centre below d/2
    EXPECT_GT(prof[5].stddev, 0.0);
    EXPECT_EQ(prof[5].periods, static_cast<std::size_t>(periods));
  }
}

TEST(VelocityProfile, SectionsAndFit) {
  const auto sec = paper_arc_sections();
  ASSERT_EQ(sec.size(), 9u);
  EXPECT_NEAR(sec[0].theta, M_PI / 4, 1e-15);
  EXPECT_NEAR(sec[8].theta, 0.75 * M_PI, 1e-15);
  EXPECT_NEAR(sec[8].z_over_length, 0.7, 1e-15);
  const double x[] = {0, 1, 2, 3}, y[] = {1, 3, 5, 7};
  const LineFit fl = fit_line(x, y, 4, 0, 10);
  EXPECT_NEAR(fl.slope, 2.0, 1e-12);
  EXPECT_NEAR(fl.intercept, 1.0, 1e-12);
  EXPECT_THROW(fit_line(x, y, 4, 5, 6), std::invalid_argument);
}

TEST(VelocityProfile, StatisticsAreOverTurnsNotParticles) {
  // Turn k puts (k + 1) particles at vz = k + 1 in one bin of the 45 deg, z/L = 0.3
  // section: the mean over turns is 2.5 (not the particle-weighted 3), std sqrt(5/3).
  const DrumFrame f = paper_view_frame(R, L);
  VelocityProfileConfig c;
  c.bins.particle_diameter = d;
  VelocityProfileSampler s(f, c);
  const double w = 2.2 * d, th = M_PI / 4;
  for (int k = 0; k < 4; ++k) {
    Particles p;
    for (int i = 0; i <= k; ++i) {
      p.add((R - w) * std::cos(th), (R - w) * std::sin(th), 0.3 * L, d / 2);
      p.vz.back() = k + 1.0;
    }
    s.add_snapshot(p.view());
    s.end_period();
  }
  const ProfileBin b = s.profile(0)[c.bins.index(w)];
  std::printf("per-turn statistics: mean %.4f (expect 2.5), std %.4f (expect %.4f), %zu turns, %zu samples\n", b.mean,
              b.stddev, std::sqrt(5.0 / 3.0), b.periods, b.samples);
  EXPECT_NEAR(b.mean, 2.5, 1e-12);
  EXPECT_NEAR(b.stddev, std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_EQ(b.periods, 4u);
  EXPECT_EQ(b.samples, 10u);
  EXPECT_EQ(s.profile(1)[c.bins.index(w)].samples, 0u);  // 90 deg section saw nothing
}
