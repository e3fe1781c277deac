// Moving/stationary zone detection on synthetic surface-velocity fields.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dem/film/film_sections.hpp"
#include "dem/film/zone_boundaries.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double deg = M_PI / 180.0;
// Surface velocity peaking at theta0, positive over +-90 deg.
double field(double th, double theta0) { return 0.5 * std::max(0.0, std::cos(th - theta0)); }
}  // namespace

TEST(ZoneBoundaries, CosineFieldCrossings) {
  const int n = 72;
  for (double theta0 : {100.0 * deg, 10.0 * deg}) {  // the second wraps through theta = 0
    std::vector<double> v(n);
    for (int k = 0; k < n; ++k) v[k] = field((k + 0.5) * 2 * M_PI / n, theta0);
    const ZoneDetection z = detect_zones(v.data(), n, 0.2);
    ASSERT_EQ(z.moving.size(), 1u);
    const double half = std::acos(0.2);  // where the field is 0.2 of its maximum
    const double start = wrap_angle(theta0 + half), end = wrap_angle(theta0 - half);
    std::printf("peak at %.0f deg: moving zone starts %.2f deg (true %.2f), ends %.2f deg (true %.2f), width %.2f deg\n",
                theta0 / deg, z.moving[0].start / deg, start / deg, z.moving[0].end / deg, end / deg,
                z.moving[0].width() / deg);
    // Linear interpolation between bin centres 5 deg apart.
    EXPECT_NEAR(std::fabs(wrap_angle(z.moving[0].start - start + M_PI) - M_PI), 0.0, 0.3 * deg);
    EXPECT_NEAR(std::fabs(wrap_angle(z.moving[0].end - end + M_PI) - M_PI), 0.0, 0.3 * deg);
    int moving_bins = 0;
    for (int m : z.zone_of_bin) moving_bins += m;
    EXPECT_NEAR(moving_bins, 2 * half / (5 * deg), 1.0);
  }
}

TEST(ZoneBoundaries, TwoArcsAndErrors) {
  const int n = 36;
  std::vector<double> v(n, 0.0);
  for (int k = 3; k < 8; ++k) v[k] = 1.0;
  for (int k = 20; k < 24; ++k) v[k] = 0.8;
  v[30] = std::nan("");
  const ZoneDetection z = detect_zones(v.data(), n, 0.5);
  ASSERT_EQ(z.moving.size(), 2u);
  EXPECT_NEAR(z.moving[0].end / deg, 30.0, 1e-9);   // halfway between bins 2 and 3 (centres 25, 35 deg)
  EXPECT_NEAR(z.moving[0].start / deg, 80.0, 1e-9);  // halfway between bins 7 and 8
  EXPECT_NEAR(z.moving[1].end / deg, 195.0 + 10 * 0.5 / 0.8, 1e-9);  // 0 -> 0.8 crosses 0.5 at 5/8
  EXPECT_NEAR(z.moving[1].start / deg, 235.0 + 10 * 0.3 / 0.8, 1e-9);  // 0.8 -> 0 crosses 0.5 at 3/8
  std::vector<double> still(n, 0.0);
  EXPECT_THROW(detect_zones(still.data(), n, 0.5), std::invalid_argument);
  EXPECT_THROW(detect_zones(v.data(), n, 0.0), std::invalid_argument);
}

TEST(ZoneBoundaries, EndToEndFromParticles) {
  // A film of random particles whose surface layer moves by the cosine field: the
  // section sampler's surface velocity (n_p innermost particles, eqs 4-7) feeds the
  // detector.
  const double d = 1.2e-3, R = 50 * d, L = 20 * d, theta0 = 95 * deg;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles p;
  for (int i = 0; i < 60000; ++i) {
    const double w = (0.5 + 3.0 * u(rng)) * d, th = 2 * M_PI * u(rng);
    p.add((R - w) * std::cos(th), (R - w) * std::sin(th), L * u(rng), d / 2);
    p.vz.back() = (w > 2.5 * d ? field(th, theta0) : 0.0);  // only the top layer moves
  }
  const DrumFrame f = paper_view_frame(R, L);
  const FilmSectionGrid g = section_grid(2, 72, d);
  FilmThicknessAccumulator acc;
  acc.add(sample_film_sections(p.view(), f, g));
  const auto v = acc.surface_velocity(0, 2);
  const ZoneDetection z = detect_zones(v.data(), v.size(), 0.2);
  ASSERT_EQ(z.moving.size(), 1u);
  const double half = std::acos(0.2);
  std::printf("particles: moving zone %.1f -> %.1f deg (true %.1f -> %.1f), peak surface u %.3f m/s\n",
              z.moving[0].start / deg, z.moving[0].end / deg, (theta0 + half) / deg, (theta0 - half) / deg,
              z.threshold / 0.2);
  EXPECT_NEAR(z.moving[0].start, theta0 + half, 3 * deg);
  EXPECT_NEAR(z.moving[0].end, theta0 - half, 3 * deg);
}
