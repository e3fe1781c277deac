// The dispersion estimator (dem/film/dispersion.hpp, docs/film_sampling.md "Wall-normal
// dispersion") on synthetic walks of known wall-normal D:
//  - a random walk with a known, depth-dependent D and a radial drift, with particles
//    leaving and joining, shuffled ids and a faster-diffusing population outside the axial
//    window: D within 5 % of the truth in every bin, the drift within 5 %;
//  - a walk between reflecting walls 3 d apart with D large enough that a 0.5 d bin is
//    crossed in 18 ms: the fit keeps the lags up to a quarter of that (4 of the 20) and D is
//    within 5 % (the fit over every lag is printed beside it);
//  - pure drift (every particle at the same radial speed, plus axial and tangential motion):
//    D = 0 to rounding, the drift recovered.
// Each prints the measured value beside the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "dem/film/dispersion.hpp"
#include "synthetic_films.hpp"

using namespace centrec::film;
using namespace centrec::film::test;

namespace {
constexpr double d = 1.2e-3, R = 50 * d, L = 0.2;
constexpr double spacing = 1e-3;  // s between samples of a burst

struct Walker {
  std::int64_t id;
  double w, theta, z;
  bool alive;
};

// One sample of the walkers in shuffled order (matching must go by id).
Particles sample(const std::vector<Walker>& ws, double time, std::mt19937_64& rng) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < ws.size(); ++i)
    if (ws[i].alive) order.push_back(i);
  std::shuffle(order.begin(), order.end(), rng);
  Particles p;
  p.time = time;
  for (std::size_t i : order) {
    const Walker& k = ws[i];
    p.add((R - k.w) * std::cos(k.theta), (R - k.w) * std::sin(k.theta), k.z, d / 2);
    p.id.back() = k.id;
  }
  return p;
}

DispersionConfig config(int bins, double width_d) {
  DispersionConfig c;
  c.bins.particle_diameter = d;
  c.bins.width_d = width_d;
  c.bins.count = bins;
  c.z_min = 0.2 * L;
  c.z_max = 0.8 * L;
  c.fine_lags = 20;
  return c;
}
}  // namespace

// Known D(w) (m^2/s) growing away from the wall. For the Ito walk w_{n+1} = w_n +
// sqrt(2 D(w_n) dt) xi with D linear in w, the variance of the displacement from w0 is
// exactly 2 D(w0) t (E[D(w_n)] = D(w0)), so a bin's truth is D at its centre.
double D_of(double w) { return 2e-7 * (1.0 + 0.5 * w / d); }

TEST(Dispersion, RandomWalkOfKnownDiffusivityWithin5Percent) {
  const DrumFrame f = paper_view_frame(R, L);
  DispersionEstimator est(f, config(16, 0.5));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double drift = 5e-3;  // m/s, dw/dt: away from the wall
  std::int64_t next_id = 0;
  double t = 1.0;
  for (int period = 0; period < 3; ++period) {
    for (int burst = 0; burst < 2; ++burst) {
      std::vector<Walker> ws;
      for (int i = 0; i < 36000; ++i) {
        // Inside the window: the walk of D_of. Outside it (z/L < 0.1, it never enters): 100x
        // faster, which must not reach the result.
        const bool inside = i % 6 != 0;
        ws.push_back({next_id++, (1.0 + 6.0 * u(rng)) * d, 2 * M_PI * u(rng),
                      inside ? (0.2 + 0.6 * u(rng)) * L : 0.1 * u(rng) * L, true});
      }
      for (int s = 0; s <= 22; ++s) {
        est.add_sample(sample(ws, t, rng).view());
        t += spacing;
        for (Walker& k : ws) {
          const double D = (k.z < 0.2 * L ? 100.0 : 1.0) * D_of(k.w);
          k.w += drift * spacing + std::sqrt(2 * D * spacing) * gauss(rng);
          k.theta += 0.3 * spacing * 100;  // carried round by the drum
          k.z += 0.2 * spacing;            // and along it (stays inside the window's starts)
          if (u(rng) < 0.002) k.alive = false;  // left through the outlet
        }
        for (int n = 0; n < 50; ++n)  // fed in
          ws.push_back({next_id++, (1.0 + 6.0 * u(rng)) * d, 2 * M_PI * u(rng), (0.2 + 0.6 * u(rng)) * L, true});
      }
      est.end_burst();
      t += 0.05;  // the rest of the snapshot interval
    }
    est.end_period();
  }
  const auto res = est.result();
  for (int k = 3; k < 13; ++k) {
    const DispersionBin& b = res[static_cast<std::size_t>(k)];
    const double expect = D_of(b.wall_distance_d * d);
    std::printf("w = %.2f d: D = %.4e m^2/s (true %.4e, %+.2f %%, tolerance 5 %%; spread over %zu turns %.1e), "
                "lags %.0f-%.0f ms, crossing time %.0f ms, drift %.5f m/s (true %.5f)\n",
                b.wall_distance_d, b.coefficient, expect, 100 * (b.coefficient / expect - 1), b.periods,
                b.coefficient_std, 1e3 * b.fit_lag_min, 1e3 * b.fit_lag_max, 1e3 * b.crossing_time, b.drift, drift);
    EXPECT_NEAR(b.coefficient / expect, 1.0, 0.05) << k;
    EXPECT_NEAR(b.drift / drift, 1.0, 0.05) << k;
    EXPECT_EQ(b.periods, 3u);
    EXPECT_GT(b.coefficient_std, 0.0);
    EXPECT_LT(b.coefficient_std, 0.1 * expect);
    EXPECT_NEAR(b.fit_lag_max, 20 * spacing, 1e-9);  // crossing time >= 0.4 s: every lag is short
  }
  // No walker inside the window starts below 1 d (the drift moves them away from the wall).
  EXPECT_EQ(res[0].samples, 0u);
  EXPECT_TRUE(std::isnan(res[0].coefficient));
  EXPECT_NEAR(est.spacing(), spacing, 1e-12);
}

TEST(Dispersion, LagsShortAgainstTheBinCrossingTime) {
  // A 3 d layer (w in [1 d, 4 d]) between reflecting walls with D = 1e-5 m^2/s: the
  // crossing time of a 0.5 d bin is 18 ms, so the 20 ms lags see the walls' bound.
  const double D = 1e-5, w0 = 1.0 * d, w1 = 4.0 * d;
  const DrumFrame f = paper_view_frame(R, L);
  DispersionEstimator est(f, config(12, 0.5));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int substeps = 20;  // the walk between samples, so the reflections are resolved
  double t = 0.0;
  std::int64_t next_id = 0;
  for (int period = 0; period < 2; ++period) {
    std::vector<Walker> ws;
    for (int i = 0; i < 50000; ++i) ws.push_back({next_id++, w0 + (w1 - w0) * u(rng), 0.0, 0.5 * L, true});
    for (int s = 0; s <= 22; ++s) {
      est.add_sample(sample(ws, t, rng).view());
      t += spacing;
      for (Walker& k : ws)
        for (int q = 0; q < substeps; ++q) {
          k.w += std::sqrt(2 * D * spacing / substeps) * gauss(rng);
          if (k.w < w0) k.w = 2 * w0 - k.w;
          if (k.w > w1) k.w = 2 * w1 - k.w;
        }
    }
    est.end_burst();
    est.end_period();
  }
  const auto res = est.result();
  const std::vector<double> tau = est.lags();
  // The bins at least 1 d from either wall: no wall within reach of the short lags.
  for (int k = 4; k < 6; ++k) {
    const DispersionBin& b = res[static_cast<std::size_t>(k)];
    const double all_lags = msd_slope_coefficient(tau, b.msd, tau.back());
    std::printf("w = %.2f d: D = %.4e m^2/s (true %.1e, %+.2f %%, tolerance 5 %%) over lags %.0f-%.0f ms "
                "(crossing time %.1f ms); over all lags to 20 ms: %.4e (%+.1f %%)\n",
                b.wall_distance_d, b.coefficient, D, 100 * (b.coefficient / D - 1), 1e3 * b.fit_lag_min,
                1e3 * b.fit_lag_max, 1e3 * b.crossing_time, all_lags, 100 * (all_lags / D - 1));
    EXPECT_NEAR(b.coefficient / D, 1.0, 0.05) << k;
    // Lags up to a quarter of the crossing time (4 ms here), not the 20 ms available.
    EXPECT_LE(b.fit_lag_max, std::max(2 * spacing, 0.25 * b.crossing_time) + 1e-12) << k;
    EXPECT_GE(b.fit_lag_max, 0.25 * b.crossing_time - spacing) << k;
  }
}

TEST(Dispersion, SaturatingMsdKeepsTheShortestLags) {
  // A 1 d layer (two bins) between reflecting walls with D = 5e-5 m^2/s: the MSD saturates
  // within a few ms, so a fit over every lag reads almost nothing (t_x then looks long and
  // every lag stays in). Started from the two shortest lags, the fit stays there and reads
  // the order of D (the walls already bound the 2 ms displacement, so it reads low).
  const double D = 5e-5, w0 = 1.0 * d, w1 = 2.0 * d;
  const DrumFrame f = paper_view_frame(R, L);
  DispersionEstimator est(f, config(6, 0.5));
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Walker> ws;
  for (int i = 0; i < 20000; ++i) ws.push_back({i, w0 + (w1 - w0) * u(rng), 0.0, 0.5 * L, true});
  for (int s = 0; s <= 22; ++s) {
    est.add_sample(sample(ws, 0.001 * s, rng).view());
    for (Walker& k : ws)
      for (int q = 0; q < 20; ++q) {
        k.w += std::sqrt(2 * D * spacing / 20) * gauss(rng);
        if (k.w < w0) k.w = 2 * w0 - k.w;
        if (k.w > w1) k.w = 2 * w1 - k.w;
      }
  }
  est.end_burst();
  est.end_period();
  const auto res = est.result();
  const std::vector<double> tau = est.lags();
  for (int k = 2; k < 4; ++k) {
    const DispersionBin& b = res[static_cast<std::size_t>(k)];
    std::printf("w = %.2f d: D = %.3e m^2/s (true %.1e, walls 0.25 d away) over lags %.0f-%.0f ms; over all lags "
                "%.3e\n",
                b.wall_distance_d, b.coefficient, D, 1e3 * b.fit_lag_min, 1e3 * b.fit_lag_max,
                msd_slope_coefficient(tau, b.msd, tau.back()));
    EXPECT_NEAR(b.fit_lag_max, 2 * spacing, 1e-9) << k;
    EXPECT_GT(b.coefficient, 0.3 * D) << k;
  }
}

TEST(Dispersion, PureDriftGivesZero) {
  const DrumFrame f = paper_view_frame(R, L);
  DispersionEstimator est(f, config(16, 0.5));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double drift = -4e-3;  // m/s, dw/dt: toward the wall
  std::vector<Walker> ws;
  for (int i = 0; i < 20000; ++i) ws.push_back({i, (1.0 + 6.0 * u(rng)) * d, 2 * M_PI * u(rng), (0.2 + 0.6 * u(rng)) * L, true});
  double t = 0.5;
  for (int s = 0; s <= 22; ++s) {
    est.add_sample(sample(ws, t, rng).view());
    t += spacing;
    for (Walker& k : ws) {
      k.w += drift * spacing;
      k.theta += 3.0 * spacing * (1.0 + u(rng));  // tangential and axial motion, random
      k.z += 0.5 * spacing * u(rng);
    }
  }
  est.end_burst();
  est.end_period();
  const auto res = est.result();
  for (int k = 2; k < 12; ++k) {
    const DispersionBin& b = res[static_cast<std::size_t>(k)];
    std::printf("w = %.2f d: D = %.3e m^2/s (true 0, tolerance 1e-15), drift %.6f m/s (true %.6f)\n",
                b.wall_distance_d, b.coefficient, b.drift, drift);
    EXPECT_LT(std::fabs(b.coefficient), 1e-15) << k;
    EXPECT_NEAR(b.drift, drift, 1e-6 * std::fabs(drift)) << k;
  }
}

TEST(Dispersion, RejectsUnevenSpacingAndBackwardSamples) {
  const DrumFrame f = paper_view_frame(R, L);
  DispersionEstimator est(f, config(16, 0.5));
  Particles a;
  a.add(R - d, 0, 0.5 * L, d / 2);
  a.time = 0.0;
  est.add_sample(a.view());
  a.time = 0.001;
  est.add_sample(a.view());
  a.time = 0.0025;
  EXPECT_THROW(est.add_sample(a.view()), std::invalid_argument);
  a.time = 0.0005;
  EXPECT_THROW(est.add_sample(a.view()), std::invalid_argument);
  est.end_burst();  // a new burst may start anywhere, but keeps the spacing
  a.time = 5.0;
  est.add_sample(a.view());
  a.time = 5.002;
  EXPECT_THROW(est.add_sample(a.view()), std::invalid_argument);
}

TEST(Dispersion, CheckpointContinuesExactly) {
  const DrumFrame f = paper_view_frame(R, L);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Walker> ws;
  for (int i = 0; i < 2000; ++i) ws.push_back({i, (1.0 + 0.003 * i) * d, 0.001 * i, 0.5 * L, true});
  std::vector<Particles> samples;
  for (int s = 0; s < 40; ++s) {
    samples.push_back(sample(ws, 0.001 * s, rng));
    for (Walker& k : ws) k.w += 1e-5 * gauss(rng);
  }
  auto run = [&](DispersionEstimator& e, int from, int to) {
    for (int s = from; s < to; ++s) {
      e.add_sample(samples[static_cast<std::size_t>(s)].view());
      if (s % 20 == 19) e.end_burst(), e.end_period();
    }
  };
  DispersionEstimator straight(f, config(16, 0.5)), first(f, config(16, 0.5)), second(f, config(16, 0.5));
  run(straight, 0, 40);
  run(first, 0, 20);
  PackedState st;
  first.save(st);
  StateReader in(st.data, "test");
  second.load(in);
  in.finish();
  run(second, 20, 40);
  const auto a = straight.result(), b = second.result();
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(std::isnan(a[k].coefficient), std::isnan(b[k].coefficient));
    if (std::isfinite(a[k].coefficient)) {
      EXPECT_EQ(a[k].coefficient, b[k].coefficient);
      EXPECT_EQ(a[k].coefficient_std, b[k].coefficient_std);
    }
  }
}
