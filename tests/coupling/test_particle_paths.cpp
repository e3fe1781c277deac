// Particle tracks of a fed drum (dem/film/particle_tracks.hpp) and heating along the paths
// (coupling/particle_path_heating.hpp) on synthetic drums whose answers are known:
// residence times of a plug flow and of a fast and a slow stream, the window's weighting,
// and a particle relaxing towards a film that warms linearly along its path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupling/particle_path_heating.hpp"
#include "dem/film/particle_tracks.hpp"

namespace {

using centrec::film::TrackSnapshot;

// A drum of length L fed one particle every `feed_every` s from t = -lead; particle k moves
// along z at speed u(k) from z_feed and leaves at z_exit, eta0 from the wall (r = R - eta0).
// Snapshots every `spacing` s from 0 to `window`.
struct SyntheticDrum {
  double L = 0.1, R = 0.05, eta0 = 1e-3;
  double z_feed = 0.0, z_exit = 0.1;  // m: where particles appear and leave
  double feed_every = 0.01, lead = 20.0, spacing = 0.04, window = 12.0;
  template <class Speed>
  std::vector<TrackSnapshot> tracks(Speed&& u) const {
    std::vector<TrackSnapshot> out;
    const int n_feed = static_cast<int>((lead + window) / feed_every);
    for (double t = 0.0; t <= window + 1e-9; t += spacing) {
      TrackSnapshot s;
      s.time = t;
      for (int k = 0; k < n_feed; ++k) {
        const double t_feed = -lead + k * feed_every, age = t - t_feed;
        if (age < 0.0) continue;
        const double z = z_feed + u(k) * age;
        if (z >= z_exit) continue;
        s.id.push_back(k);
        s.z.push_back(z);
        s.r.push_back(R - eta0);
      }
      out.push_back(std::move(s));
    }
    return out;
  }
};

}  // namespace

TEST(ParticleTracks, APlugFlowsResidenceIsLengthOverSpeed) {
  const SyntheticDrum drum;
  const double u = 0.02;  // m/s: 5 s in the drum
  const auto tracks = drum.tracks([&](int) { return u; });
  const auto paths = centrec::film::complete_paths(tracks);
  const auto rt = centrec::film::residence_times(tracks, paths);
  std::printf("plug flow: %zu complete paths, mean %.4f s (L / u = %.4f s), 5/95 %% %.4f / %.4f s, coverage %.3f\n",
              paths.size(), rt.mean(), drum.L / u, rt.quantile(0.05), rt.quantile(0.95), rt.coverage());
  EXPECT_GT(paths.size(), 500u);
  EXPECT_NEAR(rt.mean(), drum.L / u, drum.spacing);  // entry and exit each within half a spacing
  EXPECT_NEAR(rt.quantile(0.05), drum.L / u, drum.spacing);
  EXPECT_NEAR(rt.quantile(0.95), drum.L / u, drum.spacing);
  EXPECT_NEAR(rt.coverage(), 1.0, 0.02);
  for (const auto& p : paths) ASSERT_EQ(p.z.size(), p.r.size());
}

TEST(ParticleTracks, TheWindowsWeightsGiveTheFeedsShares) {
  // Every 10th particle rides a fast stream (0.2 s), the rest a slow film (8 s): over a 12 s
  // window the fast ones complete ~3x more often per feed; weighted, they are 10 % again.
  const SyntheticDrum drum;
  const double u_fast = drum.L / 0.2, u_slow = drum.L / 8.0;
  const auto tracks = drum.tracks([&](int k) { return k % 10 == 0 ? u_fast : u_slow; });
  const auto paths = centrec::film::complete_paths(tracks);
  const auto rt = centrec::film::residence_times(tracks, paths);
  std::size_t fast = 0;
  for (const double t : rt.tau) fast += t < 1.0;
  const double raw = static_cast<double>(fast) / static_cast<double>(rt.tau.size());
  const double expect_mean = 0.1 * 0.2 + 0.9 * 8.0;
  std::printf("fast + slow: unweighted fast share %.3f, weighted %.3f (fed 0.100); mean %.3f s (expected %.3f s)\n",
              raw, rt.share_below(1.0), rt.mean(), expect_mean);
  EXPECT_GT(raw, 0.2);  // what the window alone shows
  EXPECT_NEAR(rt.share_below(1.0), 0.1, 0.01);
  EXPECT_NEAR(rt.mean(), expect_mean, 0.05);
  EXPECT_NEAR(rt.coverage(), 1.0, 0.03);
}

TEST(ParticleTracks, AParticleMissingFromASnapshotIsRefused) {
  const SyntheticDrum drum;
  auto tracks = drum.tracks([](int) { return 0.02; });
  const auto mid = static_cast<std::ptrdiff_t>(tracks[5].id.size() / 2);
  tracks[5].id.erase(tracks[5].id.begin() + mid);
  tracks[5].z.erase(tracks[5].z.begin() + mid);
  tracks[5].r.erase(tracks[5].r.begin() + mid);
  EXPECT_THROW(centrec::film::complete_paths(tracks), std::invalid_argument);
}

TEST(ParticlePathHeating, ARelaxingParticleLagsALinearlyWarmingFilmByRateTimesTau) {
  // The film warms linearly along z, T = T_in + G z; a particle moving at u sees it warm at
  // a = G u and lags by a tau (1 - exp(-t / tau)) (constant c_p and k_c: tau constant).
  SyntheticDrum drum;
  drum.z_feed = 0.01;  // inside the grid's first and last centres, where the field is linear
  drum.z_exit = 0.09;
  const double u = 0.02, G = 4000.0, T_in = 873.15;
  const auto tracks = drum.tracks([&](int) { return u; });
  const auto paths = centrec::film::complete_paths(tracks);
  const auto rt = centrec::film::residence_times(tracks, paths);
  centrec::coupling::FilmTemperatureField field;
  field.length = drum.L;
  const int nz = 50, nxi = 4;
  field.nxi = nxi;
  for (int i = 0; i < nz; ++i) {
    field.z.push_back((i + 0.5) * drum.L / nz);
    field.thickness.push_back(4e-3);
    for (int j = 0; j < nxi; ++j) {
      field.T.push_back(T_in + G * field.z.back());
      field.k_conduction.push_back(0.5);
    }
  }
  centrec::coupling::PathHeatingSpec spec;
  spec.drum_radius = drum.R;
  spec.T_in = T_in;
  spec.heat.cp_constant = 1200.0;
  const double tau = spec.material.rho_s * 1200.0 * spec.material.d * spec.material.d / (12.0 * 0.5);
  const auto heated = centrec::coupling::heat_paths(paths, rt.weight, tracks, field, spec);
  spec.relax = false;
  const auto read = centrec::coupling::heat_paths(paths, rt.weight, tracks, field, spec);
  ASSERT_EQ(heated.size(), paths.size());
  double worst = 0.0, worst_read = 0.0;
  std::size_t checked = 0;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    // The path's first point is at T_in + G z0 (the particle enters at T_in below it); from
    // there the film warms at a and the particle's offset decays.
    const auto& path = paths[p];
    const double z0 = path.z.front(), z1 = path.z.back();
    const double t = (z1 - z0) / u, a = G * u;
    const double Tf0 = T_in + G * z0, Tf1 = T_in + G * z1;
    ++checked;
    const double expect = Tf1 - a * tau * (1.0 - std::exp(-t / tau)) + (T_in - Tf0) * std::exp(-t / tau);
    worst = std::max(worst, std::abs(heated[p].T_out - expect));
    worst_read = std::max(worst_read, std::abs(read[p].T_out - Tf1));
  }
  std::printf(
      "tau %.4f s, %zu paths: largest difference from the analytic lag %.3g K (lag at exit %.2f K); tau = 0 "
      "reads the field to %.3g K\n",
      tau, checked, worst, G * u * tau * (1.0 - std::exp(-4.0 / tau)), worst_read);
  EXPECT_GT(checked, 500u);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_read, 1e-9);
}

TEST(ParticlePathHeating, AParticleAboveTheFilmExchangesNothing) {
  const SyntheticDrum drum;
  auto tracks = drum.tracks([](int) { return 0.02; });
  for (auto& s : tracks)
    for (auto& r : s.r) r = drum.R - 10e-3;  // 10 mm from the wall, over a 4 mm film
  const auto paths = centrec::film::complete_paths(tracks);
  const auto rt = centrec::film::residence_times(tracks, paths);
  centrec::coupling::FilmTemperatureField field;
  field.length = drum.L;
  field.nxi = 1;
  field.z = {0.25 * drum.L, 0.75 * drum.L};
  field.thickness = {4e-3, 4e-3};
  field.T = {1200.0, 1200.0};
  field.k_conduction = {0.5, 0.5};
  centrec::coupling::PathHeatingSpec spec;
  spec.drum_radius = drum.R;
  spec.T_in = 873.15;
  const auto heated = centrec::coupling::heat_paths(paths, rt.weight, tracks, field, spec);
  ASSERT_FALSE(heated.empty());
  for (const auto& h : heated) EXPECT_EQ(h.T_out, 873.15);
}
