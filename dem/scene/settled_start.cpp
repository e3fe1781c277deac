#include "dem/scene/settled_start.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "dem/first_half_step.hpp"
#include "dem/scene/wall_lattice.hpp"

namespace centrec::dem::scene {

namespace {

bool same(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b)); }

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("dem.initial_film.from_run: " + what);
}

// Axial distance between lattice rows and the first row's centre, as wall_lattice.cpp lays them.
struct Rows {
  double spacing = 0.0, first = 0.0;
};
Rows lattice_rows(const SceneConfig& c) {
  const RoughWallSpec& w = c.rough_wall;
  const double row = w.lattice == Lattice::hexagonal ? w.spacing * std::sqrt(3.0) / 2.0 : w.spacing;
  if (!c.slice.enabled) return {row, 0.5 * w.sphere_diameter};
  int n = static_cast<int>(std::floor(c.slice.length / row));
  if (w.lattice == Lattice::hexagonal && n % 2) --n;
  const double dz = c.slice.length / n;
  return {dz, 0.5 * dz};
}

// The fraction f of `film` in every axial section of length `section`, the particles nearest
// the axis (the film's top) left out; the totals kept are rounded cumulatively, so the whole
// film keeps f of its particles to within one.
std::vector<InitialFilmSpec::Particle> keep_lower_fraction(std::vector<InitialFilmSpec::Particle> film, double f,
                                                           double section) {
  auto index = [section](const InitialFilmSpec::Particle& p) { return static_cast<long>(std::floor(p.x.z / section)); };
  auto rho2 = [](const InitialFilmSpec::Particle& p) { return p.x.x * p.x.x + p.x.y * p.x.y; };
  std::stable_sort(film.begin(), film.end(), [&](const auto& a, const auto& b) {
    const long ia = index(a), ib = index(b);
    return ia != ib ? ia < ib : rho2(a) > rho2(b);
  });
  std::vector<InitialFilmSpec::Particle> kept;
  std::size_t seen = 0;
  for (std::size_t b = 0; b < film.size();) {
    std::size_t e = b;
    while (e < film.size() && index(film[e]) == index(film[b])) ++e;
    seen += e - b;
    const std::size_t total = static_cast<std::size_t>(std::llround(f * static_cast<double>(seen)));
    for (std::size_t i = b; i < e && kept.size() < total; ++i) kept.push_back(film[i]);
    b = e;
  }
  return kept;
}

// The index of each glued sphere of `state` among the target's lattice `sites`
// (rough_wall_centres at angle 0), by position once turned back; absent where the target
// has none there.
std::unordered_map<std::int64_t, std::int64_t> glued_in_target(const SimulationState& state, const SceneConfig& target,
                                                              const std::vector<Vec3>& sites, double c, double s) {
  std::unordered_map<std::int64_t, std::int64_t> out;
  const double cell = target.rough_wall.sphere_diameter, tol = 1e-6 * cell;
  auto key = [cell](Vec3 x) {
    return std::array<long, 3>{std::lround(x.x / cell), std::lround(x.y / cell), std::lround(x.z / cell)};
  };
  std::map<std::array<long, 3>, std::vector<std::int64_t>> grid;
  for (std::size_t k = 0; k < sites.size(); ++k) grid[key(sites[k])].push_back(static_cast<std::int64_t>(k));
  for (std::size_t i = 0; i < state.id.size(); ++i) {
    if (state.motion[i] == Motion::free) continue;
    const Vec3 x = rotate(state.x[i], Vec3{0, 0, 1}, c, -s);
    const std::array<long, 3> k0 = key(x);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({k0[0] + dx, k0[1] + dy, k0[2] + dz});
          if (it == grid.end()) continue;
          for (std::int64_t k : it->second)
            if (norm(sites[static_cast<std::size_t>(k)] - x) < tol) out[state.id[i]] = k;
        }
  }
  return out;
}

// The walls a drum scene builds, in order (CentrecScene::build_walls): the shell, the back
// plate if any, the outlet lip if any. Equal lists keep wall indices.
bool same_walls(const SceneConfig& a, const SceneConfig& b) {
  return a.drum.back_plate == b.drum.back_plate && (a.drum.lip_height > 0.0) == (b.drum.lip_height > 0.0);
}

// The contact histories of the laid film's particles (numbered as the scene adds them:
// glued 0..G-1 in lattice order, then film.settled in order), turned back by the drum's
// angle as the positions are.
void carry_contacts(const SceneConfig& source, const SimulationState& state, const SceneConfig& target,
                    InitialFilmSpec& film) {
  const double c = std::cos(state.drum_angle), s = std::sin(state.drum_angle);
  const Vec3 axis{0, 0, 1};
  auto turned_back = [&](const ContactHistory& h) {
    return ContactHistory{rotate(h.shear, axis, c, -s), rotate(h.roll, axis, c, -s)};
  };
  const std::vector<Vec3> sites =
      target.rough_wall.enabled
          ? rough_wall_centres(target.rough_wall, 0.5 * target.drum.diameter, 0.0, target.drum.length, false)
          : std::vector<Vec3>{};
  std::unordered_map<std::int64_t, std::int64_t> number = glued_in_target(state, target, sites, c, s);
  const std::int64_t glued = static_cast<std::int64_t>(sites.size());
  for (std::size_t k = 0; k < film.settled.size(); ++k)
    number[film.settled[k].source_id] = glued + static_cast<std::int64_t>(k);
  for (const PairHistoryEntry& e : state.pair_history) {
    const auto a = number.find(e.id_lo), b = number.find(e.id_hi);
    if (a == number.end() || b == number.end()) continue;
    if (a->second < glued && b->second < glued) continue;  // glued on glued: no contact the film needs
    // A history is the lower id's (dem/neighbour_list.hpp): where the new numbering swaps the
    // pair, it is the other particle's, the same vectors reversed.
    ContactHistory h = turned_back(e.history);
    if (a->second > b->second) h = ContactHistory{-1.0 * h.shear, -1.0 * h.roll};
    film.settled_contacts.push_back({std::min(a->second, b->second), std::max(a->second, b->second), h});
  }
  if (!same_walls(source, target)) return;
  const std::size_t walls = state.wall_origins.size();
  std::unordered_map<std::int64_t, std::size_t> index_of_id;
  for (std::size_t i = 0; i < state.id.size(); ++i) index_of_id[state.id[i]] = i;
  for (std::size_t k = 0; k < film.settled.size(); ++k) {
    const std::size_t i = index_of_id.at(film.settled[k].source_id);
    for (std::size_t w = 0; w < walls; ++w) {
      const ContactHistory& h = state.wall_history[i * walls + w];
      if (!is_zero(h))
        film.settled_wall_contacts.push_back({glued + static_cast<std::int64_t>(k), static_cast<int>(w), turned_back(h)});
    }
  }
}

}  // namespace

InitialFilmSpec settled_film(const SceneConfig& source, const SimulationState& state, const SceneConfig& target) {
  if (target.slice.enabled) refuse("a slice fills its period itself; a settled start is for a drum");
  if (!same(source.drum.diameter, target.drum.diameter))
    refuse("the run's drum diameter " + std::to_string(source.drum.diameter) + " m differs from this case's " +
           std::to_string(target.drum.diameter) + " m (dem.drum.diameter)");
  if (!same(source.particle.diameter, target.particle.diameter))
    refuse("the run's particle diameter differs from this case's (dem.particle)");
  const RoughWallSpec &a = source.rough_wall, &b = target.rough_wall;
  if (a.enabled != b.enabled || (b.enabled && (a.lattice != b.lattice || !same(a.spacing, b.spacing) ||
                                               !same(a.sphere_diameter, b.sphere_diameter))))
    refuse("the run's rough wall (dem.rough_wall: lattice, spacing, sphere diameter) differs from this case's");
  double shift = 0.0;  // axial offset that puts the source's lattice rows on the target's
  double period = 0.0;
  if (source.slice.enabled) {
    period = source.slice.length;
    if (b.enabled) {
      const Rows s = lattice_rows(source), t = lattice_rows(target);
      if (!same(s.spacing, t.spacing))
        refuse("the slice's lattice rows are " + std::to_string(s.spacing) + " m apart, the drum's " +
               std::to_string(t.spacing) + " m: give the slice a length of whole rows (dem.slice.length_d)");
      shift = t.first - s.first;
    }
  }
  const double L = target.drum.length;
  // Turn back by the angle the state's drum has turned; re-base the motion to the new speed.
  const double angle = state.drum_angle, c = std::cos(angle), s = std::sin(angle);
  const Vec3 axis{0, 0, 1};
  const double w_old = source.drum.omega, w_new = target.drum.omega;
  std::vector<InitialFilmSpec::Particle> out;
  for (std::size_t i = 0; i < state.id.size(); ++i) {
    if (state.motion[i] != Motion::free) continue;
    const double r = state.radius[i];
    const Vec3 x = rotate(state.x[i], axis, c, -s);
    const Vec3 v_wall_frame = rotate(state.v[i] - cross(w_old * axis, state.x[i]), axis, c, -s);
    const Vec3 w_wall_frame = rotate(state.w[i] - w_old * axis, axis, c, -s);
    const int copies = source.slice.enabled ? static_cast<int>(std::ceil(L / period)) + 1 : 1;
    for (int k = 0; k < copies; ++k) {
      Vec3 p = x;
      p.z += shift + k * period;
      // A slice's copy must not cross the back plate or the outlet; a drum's particle stays
      // where it was (one pressed against a plate overlaps it as it did) unless it lies past
      // this drum's length.
      if (source.slice.enabled ? (p.z < r || p.z > L - r) : (p.z < 0.0 || p.z > L)) continue;
      out.push_back({r, p, v_wall_frame + cross(w_new * axis, p), w_wall_frame + w_new * axis, state.id[i]});
    }
  }
  const double f = target.initial_film.holdup_fraction;
  if (!(f > 0.0 && f <= 1.0)) refuse("holdup_fraction " + std::to_string(f) + " is not in (0, 1]");
  if (f < 1.0) out = keep_lower_fraction(std::move(out), f, target.particle.diameter);
  if (out.empty()) refuse("the run's state holds no free particle inside this drum's length");
  InitialFilmSpec film = target.initial_film;
  film.settled = std::move(out);
  if (!source.slice.enabled) carry_contacts(source, state, target, film);
  return film;
}

}  // namespace centrec::dem::scene
