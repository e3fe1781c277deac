// A settled start (dem/scene/settled_start.hpp): a slice's film laid end to end along a
// drum sits in the drum's glued lattice exactly as it sat in the slice's (no new overlap),
// keeps its holdup per length and its motion relative to the wall (re-based to a new
// drum speed), and the drum it starts runs; a different drum diameter is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/settled_start.hpp"
#include "dem/scene/wall_lattice.hpp"
#include "slice_case.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

namespace {

// Smallest surface gap (negative: overlap) between the free particles and the glued spheres.
double smallest_gap(const std::vector<Vec3>& x, const std::vector<double>& r, const std::vector<Vec3>& glued, double rg,
                    double period) {
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const Vec3& g : glued) {
      Vec3 d = x[i] - g;
      if (period > 0.0) d.z -= period * std::round(d.z / period);
      if (std::fabs(d.z) > 3 * rg) continue;
      gap = std::min(gap, norm(d) - r[i] - rg);
    }
  return gap;
}

}  // namespace

TEST(SettledStart, SliceFilmLaidAlongTheDrumSitsInItsLattice) {
  SceneConfig slice = centrec::testing::controlled_slice(400, 0.0);
  slice.threads = 1;
  CentrecScene source(slice);
  source.advance(0.02);  // the film settles onto the lattice and the drum turns (1000 steps)
  const SimulationState state = source.simulation().export_state();
  const double d = slice.particle.diameter, Ls = slice.slice.length;

  SceneConfig drum = slice;
  drum.slice.enabled = false;
  drum.slice.target_mass_flow = 0.0;
  drum.drum.length = 20 * d;
  drum.feeder.enabled = false;
  drum.drum.omega = 1.1 * slice.drum.omega;  // a nearby operating point
  const std::vector<InitialFilmSpec::Particle> film = settled_film(slice, state, drum);

  // Holdup per length: the slice's free mass per period, over the drum's length less the
  // ends (particles crossing the back plate or the outlet are left out).
  std::size_t slice_free = 0;
  std::vector<Vec3> xs;
  std::vector<double> rs;
  for (std::size_t i = 0; i < state.id.size(); ++i)
    if (state.motion[i] == Motion::free) {
      ++slice_free;
      xs.push_back(state.x[i]);
      rs.push_back(state.radius[i]);
    }
  const double expected = slice_free * drum.drum.length / Ls;
  std::vector<Vec3> xd;
  std::vector<double> rd;
  for (const auto& p : film) {
    xd.push_back(p.x);
    rd.push_back(p.radius);
    EXPECT_GE(p.x.z, p.radius);
    EXPECT_LE(p.x.z, drum.drum.length - p.radius);
  }
  // Each laid particle is a slice particle turned back with the lattice and moved along by
  // whole periods, with the same velocity relative to the wall (re-based to the new speed).
  const double angle = state.drum_angle;
  std::size_t matched = 0;
  double worst = 0.0;
  for (const auto& p : film) {
    const Vec3 back{p.x.x * std::cos(angle) - p.x.y * std::sin(angle), p.x.x * std::sin(angle) + p.x.y * std::cos(angle),
                    p.x.z - Ls * std::floor(p.x.z / Ls)};
    for (std::size_t i = 0; i < state.id.size(); ++i) {
      if (state.motion[i] != Motion::free || norm(state.x[i] - back) > 1e-9 * d) continue;
      ++matched;
      const double rel_src = norm(state.v[i] - cross(Vec3{0, 0, slice.drum.omega}, state.x[i]));
      const double rel_new = norm(p.v - cross(Vec3{0, 0, drum.drum.omega}, p.x));
      worst = std::max(worst, std::fabs(rel_new - rel_src));
      break;
    }
  }
  EXPECT_EQ(matched, film.size());
  EXPECT_LT(worst, 1e-12);

  const double R = 0.5 * drum.drum.diameter, rg = 0.5 * drum.rough_wall.sphere_diameter;
  std::vector<Vec3> glued_slice;  // the slice's glued layer as it has turned
  for (std::size_t i = 0; i < state.id.size(); ++i)
    if (state.motion[i] != Motion::free) glued_slice.push_back(state.x[i]);
  const double gap_slice = smallest_gap(xs, rs, glued_slice, rg, Ls);
  const double gap_drum = smallest_gap(xd, rd, rough_wall_centres(drum.rough_wall, R, 0.0, drum.drum.length, false), rg, 0.0);
  std::printf("settled start: %zu slice particles over %.3g d -> %zu in a %.3g d drum (%.1f expected less the ends); "
              "smallest gap to the glued layer %.4g d in the slice, %.4g d in the drum; %zu matched to a slice "
              "particle, largest change of the speed relative to the wall %.3g m/s\n",
              slice_free, Ls / d, film.size(), drum.drum.length / d, expected, gap_slice / d, gap_drum / d, matched,
              worst);
  EXPECT_NEAR(gap_drum, gap_slice, 1e-9 * d);  // the same contacts with the lattice, no new overlap
  EXPECT_LT(static_cast<double>(film.size()), expected);
  EXPECT_GT(static_cast<double>(film.size()), expected - 2.0 * slice_free * d / Ls);  // at most 1 d lost at each end

  // The drum started from it runs (no blow-up from an overlap) and keeps its particles.
  drum.initial_film.settled = film;
  CentrecScene started(drum);
  EXPECT_EQ(started.free_particles(), static_cast<std::int64_t>(film.size()));
  EXPECT_NO_THROW(started.advance(0.004));
}

TEST(SettledStart, RefusesAnotherDrumDiameterOrASliceTarget) {
  SceneConfig slice = centrec::testing::controlled_slice(200, 0.0);
  slice.threads = 1;
  CentrecScene source(slice);
  const SimulationState state = source.simulation().export_state();
  SceneConfig drum = slice;
  drum.slice.enabled = false;
  drum.drum.length = 10 * slice.particle.diameter;
  drum.drum.diameter *= 1.5;
  try {
    settled_film(slice, state, drum);
    FAIL() << "another diameter accepted";
  } catch (const std::invalid_argument& e) {
    std::printf("refused: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("dem.drum.diameter"), std::string::npos);
  }
  EXPECT_THROW(settled_film(slice, state, slice), std::invalid_argument);
}

// holdup_fraction: every axial section of one diameter keeps that fraction of the laid film
// (to within one particle), and what it keeps is the film's base: no kept particle sits
// nearer the axis than a left-out one of its section.
TEST(SettledStart, HoldupFractionKeepsEachSectionsBase) {
  SceneConfig slice = centrec::testing::controlled_slice(400, 0.0);
  slice.threads = 1;
  CentrecScene source(slice);
  source.advance(0.01);
  const SimulationState state = source.simulation().export_state();
  const double d = slice.particle.diameter;
  SceneConfig drum = slice;
  drum.slice.enabled = false;
  drum.slice.target_mass_flow = 0.0;
  drum.drum.length = 20 * d;
  drum.feeder.enabled = false;
  const std::vector<InitialFilmSpec::Particle> all = settled_film(slice, state, drum);
  drum.initial_film.holdup_fraction = 0.6;
  const std::vector<InitialFilmSpec::Particle> thin = settled_film(slice, state, drum);

  auto rho = [](const InitialFilmSpec::Particle& p) { return std::hypot(p.x.x, p.x.y); };
  const int sections = 20;
  std::vector<int> n_all(sections, 0), n_thin(sections, 0);
  std::vector<double> top_kept(sections, 1e9);  // smallest radial distance kept per section
  for (const auto& p : all) ++n_all[std::min(sections - 1, static_cast<int>(p.x.z / d))];
  for (const auto& p : thin) {
    const int k = std::min(sections - 1, static_cast<int>(p.x.z / d));
    ++n_thin[k];
    top_kept[k] = std::min(top_kept[k], rho(p));
  }
  int worst_count = 0, left_out_below_kept = 0;
  for (int k = 0; k < sections; ++k) worst_count = std::max(worst_count, std::abs(n_thin[k] - static_cast<int>(std::lround(0.6 * n_all[k]))));
  for (const auto& p : all) {
    const int k = std::min(sections - 1, static_cast<int>(p.x.z / d));
    bool kept = false;
    for (const auto& q : thin) kept = kept || norm(q.x - p.x) == 0.0;
    if (!kept && rho(p) > top_kept[k]) ++left_out_below_kept;  // a left-out particle nearer the wall than a kept one
  }
  std::printf("holdup_fraction 0.6: %zu of %zu particles kept (%.4f); largest miss in a section %d particles; "
              "left-out particles nearer the wall than a kept one of their section: %d\n",
              thin.size(), all.size(), static_cast<double>(thin.size()) / all.size(), worst_count, left_out_below_kept);
  EXPECT_NEAR(static_cast<double>(thin.size()), 0.6 * all.size(), 1.0);
  EXPECT_LE(worst_count, 1);
  EXPECT_EQ(left_out_below_kept, 0);

  drum.initial_film.holdup_fraction = 1.0;
  EXPECT_EQ(settled_film(slice, state, drum).size(), all.size());
}
