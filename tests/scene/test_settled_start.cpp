// A settled start (dem/scene/settled_start.hpp): a slice's film laid end to end along a
// drum sits in the drum's glued lattice exactly as it sat in the slice's (no new overlap),
// keeps its holdup per length and its motion relative to the wall (re-based to a new
// drum speed), and the drum it starts runs; a different drum diameter is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "dem/scene/centrec_scene.hpp"
#include "dem/first_half_step.hpp"
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

// cfg with `film` as its initial film.
SceneConfig film_config(SceneConfig cfg, const InitialFilmSpec& film) {
  cfg.initial_film = film;
  return cfg;
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
  const std::vector<InitialFilmSpec::Particle> film = settled_film(slice, state, drum).settled;

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
  const std::vector<InitialFilmSpec::Particle> all = settled_film(slice, state, drum).settled;
  drum.initial_film.holdup_fraction = 0.6;
  const std::vector<InitialFilmSpec::Particle> thin = settled_film(slice, state, drum).settled;

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
  EXPECT_EQ(settled_film(slice, state, drum).settled.size(), all.size());
}

namespace {

// A short closed drum (back plate and outlet lip) of the slice's diameter on the rough wall,
// a loose film of `particles`, dt a whole turn's 1/10000 so that a run of whole turns ends
// with the lattice where it started (to round-off).
SceneConfig short_drum(std::int64_t particles) {
  SceneConfig c = centrec::testing::controlled_slice(particles, 0.0);
  c.threads = 1;
  c.slice.enabled = false;
  c.feeder.enabled = false;
  c.drum.length = 8 * c.particle.diameter;
  c.drum.lip_height = 3 * c.particle.diameter;
  c.dt = turn_period(c) / 10000.0;
  return c;
}

// The free particles' positions by id.
std::map<std::int64_t, Vec3> free_positions(const Simulation& sim) {
  std::map<std::int64_t, Vec3> x;
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (sim.motions()[i] == Motion::free) x[sim.ids()[i]] = sim.positions()[i];
  return x;
}

}  // namespace

// A drum's film laid into the same drum keeps its contact histories: the engine holds
// every contact of the kept particles (with each other, with the glued spheres matched by
// lattice position, with the walls), turned back with the drum; and the laid film goes on
// as the drum itself goes on. Without the histories the springs start unloaded and the
// film slips until they load again (a nearby operating point's start surged to 1.5x its
// feed in its first turn, docs/benchmarks.md "The fed drum").
TEST(SettledStart, DrumFilmKeepsItsContactsAndGoesOnAsTheDrumDoes) {
  const SceneConfig cfg = short_drum(300);
  CentrecScene source(cfg);
  source.advance(turn_period(cfg));  // one turn: the film settles, its springs load
  source.simulation().rebuild_lists();
  const SimulationState state = source.simulation().export_state();

  const InitialFilmSpec film = settled_film(cfg, state, cfg);
  // Expected: every contact of the source between two laid particles, or a laid one and a
  // glued sphere, and every non-zero wall history of a laid particle.
  std::map<std::int64_t, std::int64_t> number;  // source id -> the new scene's id
  std::int64_t glued = 0;
  for (std::size_t i = 0; i < state.id.size(); ++i) glued += state.motion[i] != Motion::free;
  for (std::size_t i = 0; i < state.id.size(); ++i)
    if (state.motion[i] != Motion::free) number[state.id[i]] = state.id[i];  // the lattice is built in the same order
  for (std::size_t k = 0; k < film.settled.size(); ++k) number[film.settled[k].source_id] = glued + static_cast<std::int64_t>(k);
  std::size_t expected = 0, with_glued = 0;
  double norm_src = 0.0;
  for (const PairHistoryEntry& e : state.pair_history) {
    const auto a = number.find(e.id_lo), b = number.find(e.id_hi);
    if (a == number.end() || b == number.end() || (a->second < glued && b->second < glued)) continue;
    ++expected;
    with_glued += a->second < glued || b->second < glued;
    norm_src += norm(e.history.shear) + norm(e.history.roll);
  }
  std::size_t wall_expected = 0;
  const std::size_t walls = state.wall_origins.size();
  for (std::size_t i = 0; i < state.id.size(); ++i)
    for (std::size_t w = 0; w < walls; ++w)
      wall_expected += state.motion[i] == Motion::free && number.count(state.id[i]) && !is_zero(state.wall_history[i * walls + w]);

  // What the new engine holds after its set-up, by its own export.
  CentrecScene laid(film_config(cfg, film));
  const SimulationState held = laid.simulation().export_state();
  const double c = std::cos(state.drum_angle), s = std::sin(state.drum_angle);
  std::map<std::pair<std::int64_t, std::int64_t>, ContactHistory> src;  // by the new ids, turned back
  for (const PairHistoryEntry& e : state.pair_history) {
    const auto a = number.find(e.id_lo), b = number.find(e.id_hi);
    if (a == number.end() || b == number.end()) continue;
    const double sign = a->second < b->second ? 1.0 : -1.0;  // the history is the lower id's
    src[{std::min(a->second, b->second), std::max(a->second, b->second)}] = ContactHistory{
        sign * rotate(e.history.shear, {0, 0, 1}, c, -s), sign * rotate(e.history.roll, {0, 0, 1}, c, -s)};
  }
  std::size_t held_pairs = 0, unequal = 0;
  double norm_held = 0.0;
  for (const PairHistoryEntry& e : held.pair_history) {
    if (e.id_lo < glued && e.id_hi < glued) continue;
    ++held_pairs;
    norm_held += norm(e.history.shear) + norm(e.history.roll);
    const auto it = src.find({e.id_lo, e.id_hi});
    if (it == src.end() || norm(it->second.shear - e.history.shear) > 1e-12 * norm(e.history.shear) + 1e-30 ||
        norm(it->second.roll - e.history.roll) > 1e-12 * norm(e.history.roll) + 1e-30)
      ++unequal;
  }
  std::size_t held_walls = 0;
  for (const ContactHistory& h : held.wall_history) held_walls += !is_zero(h);
  std::printf("laid film: %zu free particles of %zu; contacts in the source %zu (%zu with a glued sphere), carried %zu, "
              "held by the new engine %zu (%zu unequal to the source's turned back); history norms %.6g vs %.6g; "
              "wall histories %zu expected, %zu held\n",
              film.settled.size(), static_cast<std::size_t>(source.free_particles()), expected, with_glued,
              film.settled_contacts.size(), held_pairs, unequal, norm_src, norm_held, wall_expected, held_walls);
  ASSERT_GT(expected, 100u);
  EXPECT_GT(with_glued, 50u);
  EXPECT_EQ(film.settled_contacts.size(), expected);
  EXPECT_EQ(held_pairs, expected);
  EXPECT_EQ(unequal, 0u);
  EXPECT_NEAR(norm_held, norm_src, 1e-12 * norm_src);
  EXPECT_EQ(film.settled_wall_contacts.size(), wall_expected);
  EXPECT_EQ(held_walls, wall_expected);

  // Goes on as the drum does: the source and the laid film (with and without histories)
  // over 100 more steps, positions compared by source id in the laid frame.
  InitialFilmSpec bare = film;
  bare.settled_contacts.clear();
  bare.settled_wall_contacts.clear();
  CentrecScene unloaded(film_config(cfg, bare));
  // The set-up force pass against the source's last one (turned back): the same springs,
  // but for the one increment the set-up adds without storing it (Simulation::setup).
  auto setup_force_change = [&](const Simulation& sim) {
    std::map<std::int64_t, std::size_t> index_in_state;
    for (std::size_t j = 0; j < state.id.size(); ++j) index_in_state[state.id[j]] = j;
    double change = 0.0, total = 0.0;
    for (std::size_t i = 0; i < sim.size(); ++i) {
      if (sim.motions()[i] != Motion::free) continue;
      const std::size_t j = index_in_state.at(film.settled[static_cast<std::size_t>(sim.ids()[i] - glued)].source_id);
      const Vec3 f_src = rotate(state.f[j], {0, 0, 1}, c, -s);
      change += norm(sim.forces()[i] - f_src);
      total += norm(f_src);
    }
    return change / total;
  };
  const double change_laid = setup_force_change(laid.simulation()), change_bare = setup_force_change(unloaded.simulation());
  const int steps = 100;
  source.simulation().step(steps);
  laid.simulation().step(steps);
  unloaded.simulation().step(steps);
  const auto xs = free_positions(source.simulation()), xl = free_positions(laid.simulation()),
             xu = free_positions(unloaded.simulation());
  double dev_laid = 0.0, dev_bare = 0.0;
  for (std::size_t k = 0; k < film.settled.size(); ++k) {
    const std::int64_t id_new = glued + static_cast<std::int64_t>(k);
    const auto s_it = xs.find(film.settled[k].source_id);
    if (s_it == xs.end() || !xl.count(id_new) || !xu.count(id_new)) continue;
    const Vec3 back = rotate(s_it->second, {0, 0, 1}, c, -s);
    dev_laid = std::max(dev_laid, norm(xl.at(id_new) - back));
    dev_bare = std::max(dev_bare, norm(xu.at(id_new) - back));
  }
  const double d = cfg.particle.diameter;
  std::printf("set-up forces against the source's last (sum |df| / sum |f|): with the histories %.4f, without %.4f; "
              "after %d steps, largest distance from the drum's own run: with %.3g d, without %.3g d\n",
              change_laid, change_bare, steps, dev_laid / d, dev_bare / d);
  EXPECT_LT(change_laid, 0.05);
  EXPECT_GT(change_bare, 0.3);
  EXPECT_LT(dev_laid, 1e-3 * d);
  EXPECT_GT(dev_bare, 20.0 * dev_laid);
}
