// Simulation::export_state / import_state / rebuild_lists' partner: the engine's state
// for checkpoints (dem/simulation_state.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "dem/simulation.hpp"
#include "dem/simulation_impl.hpp"

namespace centrec::dem {

namespace {

bool same(const Material& a, const Material& b) {
  return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio && a.density == b.density;
}

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("import_state: the state does not fit this engine: " + what);
}

// Pair histories keyed by ids as a carried list (row = lower index) for the next rebuild to
// pick up. Throws with `refuse` on an id the engine does not hold.
template <class Refuse>
NeighbourList carried_list(const std::vector<PairHistoryEntry>& pairs,
                           const std::unordered_map<std::int64_t, std::int32_t>& index_of_id, std::size_t n,
                           Refuse&& refuse) {
  std::vector<std::vector<std::pair<std::int32_t, ContactHistory>>> rows(n);
  for (const PairHistoryEntry& p : pairs) {
    const auto a = index_of_id.find(p.id_lo), b = index_of_id.find(p.id_hi);
    if (a == index_of_id.end() || b == index_of_id.end() || !(p.id_lo < p.id_hi))
      refuse("contact history names unknown or unordered ids " + std::to_string(p.id_lo) + ", " +
             std::to_string(p.id_hi));
    const std::int32_t i = std::min(a->second, b->second), j = std::max(a->second, b->second);
    rows[static_cast<std::size_t>(i)].push_back({j, p.history});
  }
  NeighbourList carried;
  carried.start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& [j, h] : rows[i]) {
      carried.nbr.push_back(j);
      carried.hist.push_back(h);
    }
    carried.start[i + 1] = static_cast<std::uint32_t>(carried.nbr.size());
  }
  return carried;
}

}  // namespace

SimulationState Simulation::export_state() const {
  SimulationState s;
  s.time = time_;
  s.step = step_;
  s.dt = dt_;
  s.next_id = next_id_;
  s.drum_angle = cfg_.drum.omega * time_;
  s.materials = materials_;
  s.interactions = interactions_;
  for (const Wall& w : walls_) s.wall_origins.push_back(w.origin);
  s.wall_force = wall_force_;
  for_each_stored_particle_array(
      [&](auto array, auto stored, const char*, const char*, bool) { s.*stored = this->*array; });
  // Contacts live in the list, or (particles added/removed since) in the carried copy.
  const NeighbourList& list = dirty_ ? impl_->carried : impl_->list;
  for (std::size_t i = 0; i < list.rows(); ++i)
    for (std::uint32_t e = list.start[i]; e < list.start[i + 1]; ++e) {
      if (is_zero(list.hist[e])) continue;
      const std::int64_t a = id_[i], b = id_[static_cast<std::size_t>(list.nbr[e])];
      s.pair_history.push_back({std::min(a, b), std::max(a, b), list.hist[e]});
    }
  return s;
}

void Simulation::import_state(const SimulationState& s) {
  const std::size_t n = s.id.size();
  if (s.materials.size() != n_mat_) refuse("materials " + std::to_string(s.materials.size()) + " vs " + std::to_string(n_mat_));
  for (std::size_t k = 0; k < n_mat_; ++k)
    if (!same(s.materials[k], materials_[k])) refuse("material " + std::to_string(k) + " differs");
  if (s.interactions.size() != interactions_.size()) refuse("interaction table size");
  for (std::size_t k = 0; k < interactions_.size(); ++k)
    if (!same(s.interactions[k], interactions_[k])) refuse("interaction " + std::to_string(k) + " differs");
  if (s.wall_origins.size() != walls_.size() || s.wall_force.size() != walls_.size())
    refuse("walls " + std::to_string(s.wall_origins.size()) + " vs " + std::to_string(walls_.size()));
  for_each_stored_particle_array([&](auto, auto stored, const char* name, const char*, bool per_wall) {
    if ((s.*stored).size() != n * row_width(per_wall)) refuse(std::string(name) + " array length");
  });
  if (!(s.dt > 0.0)) refuse("dt = " + std::to_string(s.dt));

  std::unordered_map<std::int64_t, std::int32_t> index_of_id;
  index_of_id.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (s.id[i] < 0 || s.id[i] >= s.next_id) refuse("particle id " + std::to_string(s.id[i]) + " out of range");
    if (!index_of_id.emplace(s.id[i], static_cast<std::int32_t>(i)).second)
      refuse("duplicate particle id " + std::to_string(s.id[i]));
    if (s.material[i] < 0 || static_cast<std::size_t>(s.material[i]) >= n_mat_) refuse("particle material index");
    if (!(s.radius[i] > 0.0) || !is_finite(s.x[i]) || !is_finite(s.v[i]) || !is_finite(s.w[i]))
      refuse("particle id " + std::to_string(s.id[i]) + " has a bad radius or non-finite state");
  }

  // The imported particles replace every particle: their materials are the ones in use,
  // and each must have its interactions set in this engine (not just equal defaults).
  std::fill(material_in_use_.begin(), material_in_use_.end(), 0);
  std::vector<char> seen(n_mat_, 0);
  for (int m : s.material)
    if (!seen[static_cast<std::size_t>(m)]) {
      seen[static_cast<std::size_t>(m)] = 1;
      require_interactions(m, "import_state");
    }

  for (std::size_t k = 0; k < walls_.size(); ++k) walls_[k].origin = s.wall_origins[k];
  wall_force_ = s.wall_force;
  next_id_ = s.next_id;
  time_ = s.time;
  step_ = s.step;
  insert_log_.clear();
  for_each_particle_array([&](auto array, auto stored, const char*, const char*, bool per_wall) {
    if constexpr (std::is_same_v<decltype(stored), Derived>)
      (this->*array).resize(n * row_width(per_wall));  // filled below
    else
      this->*array = s.*stored;
  });
  for (std::size_t i = 0; i < n; ++i) set_mass_properties(i);  // as add_particle does

  // The pair histories as a carried list, for the rebuild to pick up.
  impl_->carried = carried_list(s.pair_history, index_of_id, n, [](const std::string& w) { refuse(w); });
  impl_->list = NeighbourList{};
  dirty_ = true;

  resolve_time_step();  // the blow-up limit for these particles
  dt_ = s.dt;
  rebuild();  // the rebuild the exporting run made in rebuild_lists(); forces are kept
  ready_ = true;
}

void Simulation::preset_contact_histories(const std::vector<PairHistoryEntry>& pairs,
                                          const std::vector<WallHistoryEntry>& walls) {
  auto refuse_preset = [](const std::string& what) -> void {
    throw std::invalid_argument("preset_contact_histories: " + what);
  };
  if (ready_) refuse_preset("only before setup(): a built list holds the contacts already");
  const std::size_t n = x_.size();
  std::unordered_map<std::int64_t, std::int32_t> index_of_id;
  index_of_id.reserve(n);
  for (std::size_t i = 0; i < n; ++i) index_of_id.emplace(id_[i], static_cast<std::int32_t>(i));
  impl_->carried = carried_list(pairs, index_of_id, n, refuse_preset);
  impl_->list = NeighbourList{};
  dirty_ = true;
  const std::size_t nw = walls_.size();
  for (const WallHistoryEntry& h : walls) {
    const auto a = index_of_id.find(h.id);
    if (a == index_of_id.end() || h.wall < 0 || static_cast<std::size_t>(h.wall) >= nw)
      refuse_preset("wall history names unknown particle " + std::to_string(h.id) + " or wall " +
                    std::to_string(h.wall));
    wall_hist_[static_cast<std::size_t>(a->second) * nw + static_cast<std::size_t>(h.wall)] = h.history;
  }
}

}  // namespace centrec::dem
