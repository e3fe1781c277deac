#include "simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "dem/first_half_step.hpp"
#include "dem/simulation_impl.hpp"
#include "dem/sphere_mass.hpp"

namespace centrec::dem {

namespace {



template <class T>
std::size_t bytes_of(const std::vector<T>& a) {
  return a.capacity() * sizeof(T);
}

// Walls a particle may touch before the next rebuild (it moves at most the skin meanwhile,
// ListSlack).
bool wall_candidate(const Wall& w, Vec3 p, double r, double margin) {
  if (!(norm2(w.velocity) == 0.0)) return true;  // moving geometry: always check
  const Vec3 d = p - w.origin;
  const double s = dot(d, w.axis);
  switch (w.shape) {
    case WallShape::plane:
      return s > -margin && s < r + margin;
    case WallShape::cylinder:
      return s >= w.axial_min - margin && s <= w.axial_max + margin && norm(d - s * w.axis) > w.radius - r - margin;
    case WallShape::disc: {
      double dist;
      Vec3 n, c;
      return !wall_geometry(w, p, dist, n, c) || dist < r + margin;
    }
  }
  return true;
}

}  // namespace


Simulation::Simulation(const SimulationConfig& config) : cfg_(config), impl_(std::make_unique<Impl>()) {
  if (cfg_.periodic_z && !(cfg_.z_hi > cfg_.z_lo))
    throw std::invalid_argument("periodic_z: z_hi must exceed z_lo");
  if (!(cfg_.skin_fraction > 0.0)) throw std::invalid_argument("skin_fraction must be > 0");
  if (!(cfg_.dt >= 0.0)) throw std::invalid_argument("dt must be >= 0 (0 = advised default)");
  if (std::fabs(norm(cfg_.drum.axis) - 1.0) > 1e-9) throw std::invalid_argument("drum.axis must be a unit vector");
  impl_->pz = {cfg_.periodic_z, cfg_.z_lo, cfg_.z_hi};
  set_threads(cfg_.threads);
}

Simulation::~Simulation() = default;

void Simulation::set_threads(int n) {
  threads_ = n > 0 ? n : omp_get_max_threads();
  if (!impl_->team || impl_->team->size() != threads_) impl_->team = std::make_unique<ThreadTeam>(threads_);
}

MaterialId Simulation::add_material(const Material& m) {
  if (!(m.youngs_modulus > 0.0) || !(m.density > 0.0) || !(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5))
    throw std::invalid_argument("material: need E > 0, density > 0, -1 < nu < 0.5");
  const std::size_t old = n_mat_;
  std::vector<PairInteraction> inter((old + 1) * (old + 1));
  std::vector<char> set((old + 1) * (old + 1), 0);
  for (std::size_t a = 0; a < old; ++a)
    for (std::size_t b = 0; b < old; ++b) {
      inter[a * (old + 1) + b] = interactions_[a * old + b];
      set[a * (old + 1) + b] = interaction_set_[a * old + b];
    }
  interactions_.swap(inter);
  interaction_set_.swap(set);
  materials_.push_back(m);
  material_in_use_.push_back(0);
  n_mat_ = old + 1;
  update_pair_constants();
  return MaterialId(static_cast<int>(old));
}

void Simulation::set_interaction(MaterialId ma, MaterialId mb, const PairInteraction& p) {
  const int a = ma.index, b = mb.index;
  if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= n_mat_ || static_cast<std::size_t>(b) >= n_mat_)
    throw std::invalid_argument("set_interaction: unknown material index");
  const auto check = [](const std::string& name, double v, double lo, double hi, bool lo_open) {
    if (lo_open ? (v > lo && v <= hi) : (v >= lo && v <= hi)) return;
    throw std::invalid_argument(name + " = " + std::to_string(v) + " must lie in " + (lo_open ? "(" : "[") +
                                std::to_string(lo) + ", " +
                                (hi < kInfinity ? std::to_string(hi) + "]" : std::string("inf)")));
  };
  for_each_pair_field([&](const char* name, auto m, double lo, double hi, bool lo_open,
                          const char*) { check(name, p.*m, lo, hi, lo_open); },
                      [&](const char* name, auto m, auto c) {
                        if (!is_rolling_model(p.*m))
                          throw std::invalid_argument(std::string(name) +
                                                      ": not a rolling model of dem/rolling_models.hpp");
                        const std::string model = rolling_model_info(p.*m).name;
                        for_each_rolling_coefficient(p.*m, [&](std::size_t k, const RollingCoefficient& r) {
                          check(model + " " + r.key, (p.*c)[k], r.lowest, r.highest, r.lowest_open);
                        });
                      });
  interactions_[static_cast<std::size_t>(a) * n_mat_ + b] = p;
  interactions_[static_cast<std::size_t>(b) * n_mat_ + a] = p;
  interaction_set_[static_cast<std::size_t>(a) * n_mat_ + b] = 1;
  interaction_set_[static_cast<std::size_t>(b) * n_mat_ + a] = 1;
  update_pair_constants();
}

void Simulation::require_interactions(int m, const char* what) {
  if (m < 0 || static_cast<std::size_t>(m) >= n_mat_)
    throw std::invalid_argument(std::string(what) + ": unknown material index " + std::to_string(m));
  auto need = [&](int other, const char* kind) {
    if (!interaction_set_[static_cast<std::size_t>(m) * n_mat_ + static_cast<std::size_t>(other)])
      throw std::invalid_argument(std::string(what) + ": materials " + std::to_string(m) + " and " +
                                  std::to_string(other) + " (" + kind +
                                  ") would meet but have no interaction: call set_interaction first");
  };
  material_in_use_[static_cast<std::size_t>(m)] = 1;
  for (std::size_t u = 0; u < n_mat_; ++u)
    if (material_in_use_[u]) need(static_cast<int>(u), "particles");
  for (const Wall& w : walls_) need(w.material, "a wall");
}

void Simulation::update_pair_constants() {
  pc_.resize(n_mat_ * n_mat_);
  for (std::size_t a = 0; a < n_mat_; ++a)
    for (std::size_t b = 0; b < n_mat_; ++b)
      pc_[a * n_mat_ + b] = make_pair_constants(materials_[a], materials_[b], interactions_[a * n_mat_ + b]);
}

int Simulation::add_wall(const Wall& w) {
  check_wall(w);
  if (static_cast<std::size_t>(w.material) >= n_mat_) throw std::invalid_argument("wall: unknown material index");
  for (std::size_t u = 0; u < n_mat_; ++u)
    if (material_in_use_[u] && !interaction_set_[u * n_mat_ + static_cast<std::size_t>(w.material)])
      throw std::invalid_argument("wall: its material " + std::to_string(w.material) + " and the particles' material " +
                                  std::to_string(u) + " have no interaction: call set_interaction first");
  if (walls_.size() >= static_cast<std::size_t>(kMaxWalls))
    throw std::invalid_argument("at most " + std::to_string(kMaxWalls) + " walls");
  // Re-lay the per-wall arrays (rows of walls_.size()) with one more column.
  const std::size_t nw = walls_.size();
  for_each_particle_array([&](auto array, auto, const char*, const char*, bool per_wall) {
    if (!per_wall) return;
    auto& a = this->*array;
    std::remove_reference_t<decltype(a)> wider(x_.size() * (nw + 1));
    for (std::size_t i = 0; i < x_.size(); ++i)
      for (std::size_t k = 0; k < nw; ++k) wider[i * (nw + 1) + k] = a[i * nw + k];
    a.swap(wider);
  });
  invalidate_list();  // wall candidate masks must be rebuilt
  walls_.push_back(w);
  wall_force_.push_back({});
  return static_cast<int>(nw);
}

std::size_t Simulation::wall_count() const { return walls_.size(); }
const Wall& Simulation::wall(int index) const { return walls_.at(static_cast<std::size_t>(index)); }
Vec3 Simulation::wall_force(int index) const { return wall_force_.at(static_cast<std::size_t>(index)); }

const ContactHistory& Simulation::wall_history(std::size_t index, int wall) const {
  return wall_hist_.at(index * walls_.size() + static_cast<std::size_t>(wall));
}

std::int64_t Simulation::add_particle(const ParticleInit& p) {
  if (!(p.radius > 0.0)) throw std::invalid_argument("particle radius must be > 0");
  if (!is_finite(p.x) || !is_finite(p.v) || !is_finite(p.w)) throw std::invalid_argument("particle: non-finite state");
  require_interactions(p.material.index, "particle");
  // A valid list takes the particle in at the next step without a rebuild
  // (take_in_new_particles); otherwise the next step rebuilds.
  if (!(ready_ && !dirty_)) invalidate_list();
  const std::int64_t id = next_id_++;
  if (insert_log_.empty() || insert_log_.back().first != step_) insert_log_.push_back({step_, id});
  // One zero row in every array, then the particle's values (zero torque, wall histories).
  const std::size_t i = x_.size();
  for_each_particle_array([&](auto array, auto, const char*, const char*, bool per_wall) {
    (this->*array).resize((i + 1) * row_width(per_wall));
  });
  id_[i] = id;
  x_[i] = p.x;
  x_[i].z = impl_->pz.wrap(p.x.z);
  v_[i] = p.v;
  w_[i] = p.w;
  r_[i] = p.radius;
  mat_[i] = p.material.index;
  motion_[i] = p.motion;
  set_mass_properties(i);
  f_[i] = m_[i] * cfg_.gravity;  // gravity for the first half-kick
  return id;
}

void Simulation::set_mass_properties(std::size_t i) {
  const double mass = sphere_mass(materials_[static_cast<std::size_t>(mat_[i])].density, r_[i]);
  m_[i] = mass;
  inv_m_[i] = 1.0 / mass;
  inv_inertia_[i] = 1.0 / (0.4 * mass * r_[i] * r_[i]);
}

void Simulation::invalidate_list() {
  // Keep the contacts (numbered as the particle arrays are now) for the next rebuild.
  if (dirty_) return;
  std::vector<std::int32_t> ident(x_.size());
  for (std::size_t i = 0; i < ident.size(); ++i) ident[i] = static_cast<std::int32_t>(i);
  carry_contacts(impl_->list, ident, ident, impl_->carried);
  dirty_ = true;
}

void Simulation::permute_particles(const std::vector<std::int32_t>& order) {
  for_each_particle_array([&](auto array, auto, const char*, const char*, bool per_wall) {
    permute_rows(this->*array, order, row_width(per_wall));
  });
}

std::size_t Simulation::remove_particles(const std::vector<std::int64_t>& ids) {
  if (ids.empty()) return 0;
  std::vector<std::int64_t> sorted(ids);
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int32_t> order, new_of_old(x_.size(), -1);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (std::binary_search(sorted.begin(), sorted.end(), id_[i])) continue;
    new_of_old[i] = static_cast<std::int32_t>(order.size());
    order.push_back(static_cast<std::int32_t>(i));
  }
  const std::size_t removed = x_.size() - order.size();
  if (removed == 0) return 0;
  if (ready_ && !dirty_) {
    remove_from_lists(order, new_of_old);
    return removed;
  }
  invalidate_list();
  NeighbourList kept;
  carry_contacts(impl_->carried, order, new_of_old, kept);
  impl_->carried = std::move(kept);
  permute_particles(order);
  return removed;
}

void Simulation::set_velocity(std::size_t index, Vec3 v, Vec3 w) {
  v_.at(index) = v;
  w_.at(index) = w;
}

std::ptrdiff_t Simulation::index_of(std::int64_t id) const {
  for (std::size_t i = 0; i < id_.size(); ++i)
    if (id_[i] == id) return static_cast<std::ptrdiff_t>(i);
  return -1;
}

TimeStepAdvice Simulation::time_step_advice() const {
  TimeStepAdvice a;
  a.max_impact_speed = cfg_.max_impact_speed;
  a.rayleigh_time = std::numeric_limits<double>::infinity();
  a.hertz_time = std::numeric_limits<double>::infinity();
  // Smallest radius per particle material in use.
  std::vector<double> rmin(n_mat_, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < r_.size(); ++i)
    rmin[static_cast<std::size_t>(mat_[i])] = std::min(rmin[static_cast<std::size_t>(mat_[i])], r_[i]);
  std::vector<bool> wall_mat(n_mat_, false);
  for (const Wall& w : walls_) wall_mat[static_cast<std::size_t>(w.material)] = true;
  for (std::size_t a_ = 0; a_ < n_mat_; ++a_) {
    if (!std::isfinite(rmin[a_])) continue;
    const double r = rmin[a_];
    const double m = sphere_mass(materials_[a_].density, r);
    a.rayleigh_time = std::min(a.rayleigh_time, rayleigh_time(materials_[a_], r));
    for (std::size_t b = 0; b < n_mat_; ++b) {
      const double E = pc_[a_ * n_mat_ + b].E_eff;
      if (std::isfinite(rmin[b])) {  // particle-particle: the pair of the two smallest
        const double rb = rmin[b];
        const double mb = sphere_mass(materials_[b].density, rb);
        a.hertz_time = std::min(a.hertz_time, hertz_contact_time(m * mb / (m + mb), r * rb / (r + rb), E,
                                                                 cfg_.max_impact_speed));
      }
      if (wall_mat[b]) a.hertz_time = std::min(a.hertz_time, hertz_contact_time(m, r, E, cfg_.max_impact_speed));
    }
  }
  const double tmin = std::min(a.rayleigh_time, a.hertz_time);
  a.stable_bound = std::min(TimeStepAdvice::kRayleighBound * a.rayleigh_time, TimeStepAdvice::kHertzBound * a.hertz_time);
  a.recommended = std::min(cfg_.dt_fraction * tmin, a.stable_bound);
  return a;
}

double Simulation::dt() const { return dt_; }

void Simulation::resolve_time_step() {
  if (x_.empty() && cfg_.dt == 0.0)
    throw std::invalid_argument("setup: no particles to advise a time step from; add particles or set dt");
  if (!x_.empty()) {
    const TimeStepAdvice a = time_step_advice();
    if (cfg_.verbose) std::printf("%s\n", a.report().c_str());
    if (cfg_.dt > a.stable_bound) {
      std::ostringstream msg;
      msg << "dt = " << cfg_.dt << " s exceeds the stability bound " << a.stable_bound << " s ("
          << TimeStepAdvice::kRayleighBound << " x Rayleigh time " << a.rayleigh_time << " s, "
          << TimeStepAdvice::kHertzBound << " x Hertz contact time " << a.hertz_time << " s at "
          << a.max_impact_speed << " m/s); use dt <= " << a.stable_bound << " s (recommended " << a.recommended
          << " s)";
      throw std::invalid_argument(msg.str());
    }
    dt_ = cfg_.dt > 0.0 ? cfg_.dt : a.recommended;
    if (cfg_.blowup_overlap_fraction > 0.0) {
      blowup_fraction_ = cfg_.blowup_overlap_fraction;
    } else {
      // A few % of the radius, or twice the legitimate Hertz overlap of the fastest impact.
      double worst = 0.0;
      for (std::size_t i = 0; i < r_.size(); ++i) {
        const double E = pc_[static_cast<std::size_t>(mat_[i]) * n_mat_ + static_cast<std::size_t>(mat_[i])].E_eff;
        worst = std::max(worst, hertz_max_overlap(0.5 * m_[i], 0.5 * r_[i], E, cfg_.max_impact_speed) / r_[i]);
        for (const Wall& w : walls_) {
          const double Ew = pc_[static_cast<std::size_t>(mat_[i]) * n_mat_ + static_cast<std::size_t>(w.material)].E_eff;
          worst = std::max(worst, hertz_max_overlap(m_[i], r_[i], Ew, cfg_.max_impact_speed) / r_[i]);
        }
      }
      blowup_fraction_ = std::max(0.05, 2.0 * worst);
    }
  } else {
    dt_ = cfg_.dt;
  }
}

void Simulation::setup() {
  resolve_time_step();
  rebuild();
  compute_forces(false, AfterForces::nothing);  // as LIGGGHTS set-up: forces without advancing the history
  ready_ = true;
}

void Simulation::rebuild_lists() {
  if (!ready_) {
    setup();
    return;
  }
  rebuild();
}

void Simulation::rebuild() {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& im = *impl_;
  double rmax = 0.0;
  for (double r : r_) rmax = std::max(rmax, r);
  im.skin = cfg_.skin_fraction * 2.0 * rmax;
  const double cutoff = 2.0 * rmax + im.skin;

  std::vector<std::int32_t> order = sort_into_cells(im.grid, x_, cutoff > 0 ? cutoff : 1.0, im.pz);
  std::vector<std::int32_t> new_of_old(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) new_of_old[static_cast<std::size_t>(order[k])] = static_cast<std::int32_t>(k);
  carry_contacts(dirty_ ? im.carried : im.list, order, new_of_old, im.carry_buffer);
  permute_particles(order);
  const std::size_t n = x_.size();
  im.drum_frame = scene_symmetric_about_drum();
  im.half_skin.resize(n);
  for (std::size_t i = 0; i < n; ++i) im.half_skin[i] = half_skin_of(i);
  build_neighbour_list(im.list, im.grid, x_, r_, motion_, im.skin, im.half_skin, im.pz, im.carry_buffer, *im.team,
                       im.build_scratch);
  im.touch.resize(im.list.nbr.size());
  for (std::size_t e = 0; e < im.touch.size(); ++e) im.touch[e] = !is_zero(im.list.hist[e]);
  im.routing = PartnerRouting{};  // planned by the next force pass, for its thread count
  im.share.clear();
  im.acc_f.assign(x_.size(), Vec3{});
  im.acc_t.assign(x_.size(), Vec3{});
  im.carried.nbr.clear();
  im.carried.hist.clear();
  im.carried.start.clear();

  im.x_build = x_;
  im.angle_since_build = 0.0;
  im.wall_mask.assign(n, 0u);
  for (std::size_t i = 0; i < n; ++i) im.wall_mask[i] = candidate_walls(i);
  ++im.rebuilds;
  dirty_ = false;
  times_.neighbour_build += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::uint32_t Simulation::candidate_walls(std::size_t i) const {
  if (motion_[i] != Motion::free) return 0u;
  std::uint32_t mask = 0;
  for (std::size_t w = 0; w < walls_.size(); ++w)
    if (wall_candidate(walls_[w], x_[i], r_[i], 2.0 * impl_->half_skin[i])) mask |= 1u << w;
  return mask;
}

double Simulation::half_skin_of(std::size_t i) const {
  const Impl& im = *impl_;
  const double base = 0.5 * im.skin;
  if (motion_[i] != Motion::free) return base;
  Vec3 v = v_[i];
  if (im.drum_frame) v -= cross(cfg_.drum.omega * cfg_.drum.axis, x_[i] - cfg_.drum.origin);
  const double flight = kListHorizonSteps * dt_ * norm(v);
  const double most = im.skin / cfg_.skin_fraction;  // the largest diameter
  return flight > base ? std::min(flight, std::max(most, base)) : base;
}

bool Simulation::scene_symmetric_about_drum() const {
  const DrumMotion& d = cfg_.drum;
  if (d.omega == 0.0) return false;
  auto parallel = [&](Vec3 a) { return norm(cross(a, d.axis)) < 1e-12; };
  if (impl_->pz.on && !parallel({0, 0, 1})) return false;
  for (const Wall& w : walls_) {
    if (!(norm2(w.velocity) == 0.0) || !parallel(w.axis)) return false;
    if (w.shape != WallShape::plane && norm(cross(w.origin - d.origin, d.axis)) > 1e-12) return false;
  }
  return true;
}

void Simulation::report_blow_up(std::size_t i, Vec3 x, double overlap, const std::string& partner) const {
  std::ostringstream msg;
  msg.precision(4);
  msg << "DEM blow-up at step " << step_ << " (t = " << time_ << " s): particle id " << id_[i] << " at (" << x.x
      << ", " << x.y << ", " << x.z << ") m";
  if (std::isfinite(overlap)) {
    msg << " has overlap " << overlap << " m = " << 100.0 * overlap / r_[i] << " % of its radius with " << partner
        << " (limit " << 100.0 * blowup_fraction_ << " %)";
  } else {
    msg << " has a non-finite position, force or torque";
  }
  bool recent = false;
  for (const auto& [s, first] : insert_log_)
    if (id_[i] >= first && step_ - s <= 20) recent = true;
  msg << ". Likely cause: ";
  if (recent) msg << "particles inserted overlapping (this particle was inserted within the last 20 steps); ";
  const TimeStepAdvice advice = time_step_advice();
  if (dt_ > advice.recommended)
    msg << "dt = " << dt_ << " s larger than the advised " << advice.recommended << " s; ";
  msg << "Young's modulus too high for dt = " << dt_ << " s, or impacts faster than max_impact_speed = "
      << cfg_.max_impact_speed << " m/s (Hertz contact time there " << advice.hertz_time << " s)";
  throw BlowUpError(msg.str());
}

FirstHalfStep Simulation::begin_first_half() {
  FirstHalfStep h;
  h.dt = dt_;
  h.half = 0.5 * dt_;
  h.drum = cfg_.drum;
  h.c = std::cos(h.drum.omega * dt_);
  h.s = std::sin(h.drum.omega * dt_);
  h.spin = h.drum.omega * h.drum.axis;
  if (impl_->drum_frame) impl_->angle_since_build += h.drum.omega * dt_;
  h.cb = std::cos(impl_->angle_since_build);
  h.sb = std::sin(impl_->angle_since_build);
  h.pz = impl_->pz;
  return h;
}

ListSlack Simulation::integrate_first_half() {
  const long n = static_cast<long>(x_.size());
  const FirstHalfStep h = begin_first_half();
  const Vec3* xb = impl_->x_build.data();
  const double* hs = impl_->half_skin.data();
  const int parts = n >= kMinParallelParticles ? threads_ : 1;
  std::vector<ListSlack> part_d2(static_cast<std::size_t>(parts));
  impl_->team->run(parts, [&](int p) {
    ListSlack d2;
    for (long i = range_begin(n, parts, p); i < range_begin(n, parts, p + 1); ++i)
      d2.add(h.advance(motion_[i], inv_m_[i], inv_inertia_[i], f_[i], t_[i], xb[i], x_[i], v_[i], w_[i]), hs[i]);
    part_d2[static_cast<std::size_t>(p)] = d2;
  });
  ListSlack moved;
  for (const ListSlack& d2 : part_d2) moved.add(d2);
  return moved;
}

void Simulation::step(std::int64_t nsteps) {
  if (!ready_) setup();
  // Within one call the force pass of step s also does the first half of step s + 1
  // (same operations in the same order as separate sweeps: results are unchanged); the
  // last step of the call ends with the second half kick, so between calls the state is
  // the usual end-of-step state. dirty_ changes only between calls.
  using clock = std::chrono::steady_clock;
  const auto seconds_since = [](clock::time_point t0) { return std::chrono::duration<double>(clock::now() - t0).count(); };
  ListSlack moved;
  bool started = false;  // this step's first half already done by the previous force pass
  for (std::int64_t s = 0; s < nsteps; ++s) {
    if (dirty_) rebuild();
    if (impl_->list.rows() < x_.size()) take_in_new_particles();
    if (!started) {
      const auto t0 = clock::now();
      moved = integrate_first_half();
      times_.first_half += seconds_since(t0);
    }
    for (Wall& w : walls_) w.origin += dt_ * w.velocity;
    ++step_;
    time_ += dt_;
    if (moved.exhausted()) rebuild();
    started = s + 1 < nsteps;
    const auto t0 = clock::now();
    moved = compute_forces(true, started ? AfterForces::second_and_next_first_half : AfterForces::second_half);
    times_.force_pass += seconds_since(t0);
  }
}

NeighbourStats Simulation::neighbour_stats() const {
  NeighbourStats s;
  s.pair_contacts = impl_->pair_contacts;
  s.wall_contacts = impl_->wall_contacts;
  s.list_entries = impl_->list.nbr.size();
  s.rebuilds = impl_->rebuilds;
  s.list_edits = impl_->list_edits;
  s.skin = impl_->skin;
  s.particles = x_.size();
  return s;
}

std::size_t Simulation::memory_bytes() const {
  const Impl& im = *impl_;
  std::size_t b = 0;
  for_each_particle_array([&](auto array, auto, const char*, const char*, bool) { b += bytes_of(this->*array); });
  b += im.list.bytes() + im.carried.bytes() + im.carry_buffer.bytes() + bytes_of(im.x_build) + bytes_of(im.half_skin) + bytes_of(im.wall_mask) +
       bytes_of(im.touch) + bytes_of(im.share) + bytes_of(im.routing.slot) + bytes_of(im.routing.park_start) +
       bytes_of(im.acc_f) + bytes_of(im.acc_t) +
       bytes_of(im.grid.cell_start);
  for (const auto& t : im.tallies) b += sizeof(BlockTally) + bytes_of(t.wall_force);
  return b;
}

}  // namespace centrec::dem
