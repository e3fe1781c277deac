// Engine checkpoints (dem/simulation_state.hpp): export -> import -> export is exact, and
// a run continued from an imported state is bitwise identical to the run that exported it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <tuple>

#include "dem/simulation.hpp"
#include "tests/dem/film_scene.hpp"

using namespace centrec::dem;
using centrec::dem::testing::FilmScene;

namespace {

bool bits_equal(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }
bool bits_equal(const ContactHistory& a, const ContactHistory& b) {
  return bits_equal(a.shear, b.shear) && bits_equal(a.roll, b.roll);
}

template <class T>
bool bits_equal(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!bits_equal(a[i], b[i])) return false;
  return true;
}
template <>
bool bits_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Counts the array entries that differ (bitwise) between two states; 0 = identical.
std::size_t differences(const SimulationState& a, const SimulationState& b) {
  std::size_t d = 0;
  d += std::memcmp(&a.time, &b.time, sizeof(double)) != 0;
  d += a.step != b.step;
  d += a.dt != b.dt;
  d += a.next_id != b.next_id;
  d += a.id != b.id;
  d += a.material != b.material;
  d += a.motion != b.motion;
  d += !bits_equal(a.radius, b.radius);
  d += !bits_equal(a.x, b.x) + !bits_equal(a.v, b.v) + !bits_equal(a.w, b.w);
  d += !bits_equal(a.f, b.f) + !bits_equal(a.t, b.t);
  d += !bits_equal(a.wall_force, b.wall_force) + !bits_equal(a.wall_origins, b.wall_origins);
  d += !bits_equal(a.wall_history, b.wall_history);
  d += a.pair_history.size() != b.pair_history.size();
  if (a.pair_history.size() == b.pair_history.size())
    for (std::size_t k = 0; k < a.pair_history.size(); ++k)
      d += a.pair_history[k].id_lo != b.pair_history[k].id_lo || a.pair_history[k].id_hi != b.pair_history[k].id_hi ||
           !bits_equal(a.pair_history[k].history, b.pair_history[k].history);
  return d;
}

FilmScene scene() {
  FilmScene s;
  s.drum_radius = 0.03;
  s.dt = 2e-5;
  s.threads = 2;
  s.length = 0.024;
  return s;
}

std::unique_ptr<Simulation> film(std::size_t n) {
  const FilmScene s = scene();
  SimulationConfig cfg = centrec::dem::testing::film_config(s);
  cfg.verbose = false;
  auto sim = std::make_unique<Simulation>(cfg);
  centrec::dem::testing::build_film(*sim, s, n);
  return sim;
}

std::size_t nonzero_wall_histories(const SimulationState& s) {
  std::size_t k = 0;
  for (const auto& h : s.wall_history) k += !is_zero(h);
  return k;
}

}  // namespace

TEST(CheckpointState, RoundTripIsExact) {
  auto a = film(4000);
  a->step(200);
  a->remove_particles({3, 17, 400});  // histories now wait in the carried list
  a->step(50);
  const SimulationState s1 = a->export_state();
  auto b = film(0);  // same materials and walls, no particles
  b->import_state(s1);
  const SimulationState s2 = b->export_state();
  std::printf("state: %zu particles, %zu pair histories, %zu wall histories\n", s1.id.size(), s1.pair_history.size(),
              nonzero_wall_histories(s1));
  ASSERT_GT(s1.pair_history.size(), 300u);  // a settled film: the histories are exercised
  ASSERT_GT(nonzero_wall_histories(s1), 100u);
  // Pair histories come out in list order; compare them as sets.
  auto sorted = [](SimulationState s) {
    std::sort(s.pair_history.begin(), s.pair_history.end(),
              [](const auto& p, const auto& q) { return std::tie(p.id_lo, p.id_hi) < std::tie(q.id_lo, q.id_hi); });
    return s;
  };
  // import re-sorts the particles spatially: compare after the same rebuild on `a`.
  a->rebuild_lists();
  EXPECT_EQ(differences(sorted(a->export_state()), sorted(s2)), 0u);
}

TEST(CheckpointState, ResumedRunIsBitwiseIdentical) {
  auto a = film(4000);
  a->step(150);
  a->rebuild_lists();  // as a run does right before it writes a checkpoint
  const SimulationState saved = a->export_state();
  a->step(250);
  a->remove_particles({5});
  a->step(100);

  auto b = film(0);
  b->import_state(saved);
  b->step(250);
  b->remove_particles({5});
  b->step(100);
  const SimulationState sa = a->export_state(), sb = b->export_state();
  const std::size_t diff = differences(sa, sb);
  std::printf("after 350 resumed steps: %zu differing arrays (t = %.6f s, %zu particles)\n", diff, sb.time,
              sb.id.size());
  EXPECT_EQ(diff, 0u);
  // Control: without the rebuild at the checkpoint the runs do drift apart bitwise, so
  // the test above could fail.
  auto c = film(4000);
  c->step(400);
  c->remove_particles({5});
  c->step(100);
  const SimulationState sc = c->export_state();
  std::size_t moved = 0;
  for (std::size_t i = 0; i < sc.id.size(); ++i) {
    const auto k = std::find(sa.id.begin(), sa.id.end(), sc.id[i]) - sa.id.begin();
    moved += !bits_equal(sc.x[i], sa.x[static_cast<std::size_t>(k)]);
  }
  std::printf("control without the checkpoint rebuild: %zu of %zu positions differ bitwise\n", moved, sc.id.size());
  EXPECT_GT(moved, 0u);
}

TEST(CheckpointState, RefusesAMismatchedEngine) {
  auto a = film(200);
  a->step(10);
  SimulationState s = a->export_state();
  FilmScene other = scene();
  other.periodic = true;  // one wall instead of three
  SimulationConfig cfg = centrec::dem::testing::film_config(other);
  cfg.periodic_z = true;
  cfg.z_hi = 0.1;
  Simulation b(cfg);
  EXPECT_THROW(b.import_state(s), std::invalid_argument);
  auto c = film(0);
  s.pair_history.push_back({s.next_id + 5, s.next_id + 6, {{1e-6, 0, 0}, {}}});
  EXPECT_THROW(c->import_state(s), std::invalid_argument);
}
