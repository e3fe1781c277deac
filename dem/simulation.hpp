#pragma once
// The DEM engine's public API (docs/dem_physics.md): spheres, velocity Verlet with
// rotation (LIGGGHTS nve/sphere), gravity, Hertz-Mindlin-EPSD2 contacts with particles
// and analytic walls, cell + Verlet neighbour lists with contact-history carry-over,
// spatial sorting, OpenMP threads, time-step advisor and blow-up detection.
//
// Indices vs ids: particle arrays are reordered (spatially sorted) at every neighbour-list
// rebuild and compacted on removal, so an index is valid only until the next step() or
// remove_particles(). ids() gives each particle's stable id (returned by add_particle).
//
// Determinism: forces use a half neighbour list; each pair is evaluated once (Newton's
// third law holds exactly) in a canonical operand order (lower id first). The row owner's
// share is summed directly; the shares on each partner are summed in row order, added
// straight into the partner's accumulator by the thread that owns it, or parked and summed
// after the pass when the partner is named by another thread's rows (partner_routing.hpp),
// so each thread writes only its own particles. Per-wall force
// totals are summed over fixed blocks of particles in a fixed order. Results are therefore
// bitwise identical for any thread count (tests/dem/test_thread_determinism.cpp).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/material.hpp"
#include "dem/motion.hpp"
#include "dem/simulation_state.hpp"
#include "dem/timestep_advisor.hpp"
#include "dem/vec3.hpp"
#include "dem/walls.hpp"

namespace centrec::dem {

struct FirstHalfStep;  // dem/first_half_step.hpp
struct ListSlack;     // dem/first_half_step.hpp

// Rolling model of particle-wall contacts (docs/dem_physics.md).
enum class WallRolling : std::uint8_t {
  relative,  // w_rel = w_i - wall angular velocity (physical; default)
  liggghts,  // w_rel = w_i (LIGGGHTS 3.8 mesh walls pass only a linear wall velocity)
};

struct SimulationConfig {
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s^2
  double dt = 0.0;                // s; 0 = TimeStepAdvice::recommended
  double dt_fraction = 0.1;       // default dt = dt_fraction * min(Rayleigh, Hertz time)
  double max_impact_speed = 1.0;  // m/s, for the Hertz contact time and blow-up threshold
  double skin_fraction = 0.2;     // Verlet skin = skin_fraction * largest diameter
  // Blow-up: overlap above this fraction of the smaller radius stops the run. 0 = auto:
  // max(0.05, 2 x the Hertz overlap at max_impact_speed / R).
  double blowup_overlap_fraction = 0.0;
  bool periodic_z = false;  // periodic along z in [z_lo, z_hi) (minimum image)
  double z_lo = 0.0, z_hi = 0.0;
  DrumMotion drum;
  WallRolling wall_rolling = WallRolling::relative;
  int threads = 0;       // OpenMP threads; 0 = omp_get_max_threads()
  // Speed only: where the build has the AVX2 pair batch (dem/pair_batch_avx2.hpp), false
  // evaluates the pair contact law one pair at a time instead. The same bits either way.
  bool pair_batch = true;
  bool verbose = true;  // print the time-step advice (one line) at set-up
};

// A particle to insert. Material, radius and position have no default: `ParticleInit p;`
// does not compile, and every particle names the material it is made of.
struct ParticleInit {
  ParticleInit(MaterialId material_, double radius_, Vec3 x_, Vec3 v_ = {}, Vec3 w_ = {},
               Motion motion_ = Motion::free)
      : material(material_), radius(radius_), x(x_), v(v_), w(w_), motion(motion_) {}
  MaterialId material;  // from Simulation::add_material
  double radius;        // m (> 0)
  Vec3 x, v, w;         // position m, velocity m/s, angular velocity rad/s
  Motion motion;
};

struct NeighbourStats {
  std::size_t pair_contacts = 0;     // particle pairs in contact after the last force pass
  std::size_t wall_contacts = 0;     // particle-wall contacts after the last force pass
  std::size_t list_entries = 0;      // neighbour-list entries (each pair once)
  std::size_t rebuilds = 0;          // neighbour-list rebuilds (each also re-sorts)
  std::size_t list_edits = 0;        // insertions / removals worked into the lists without a rebuild
  double skin = 0.0;                 // m
  std::size_t particles = 0;
  // Contacts per particle as LIGGGHTS counts them: (2 pair contacts + wall contacts) / N.
  double contacts_per_particle() const {
    return particles ? (2.0 * pair_contacts + wall_contacts) / static_cast<double>(particles) : 0.0;
  }
};

// Wall-clock seconds the engine has spent in each of its phases (speed records:
// summary.json, docs/benchmarks.md). The force pass fuses the pair contacts, the wall
// contacts and the integration into one sweep per step, so they are one figure here (the
// split within it comes from a profiler, docs/benchmarks.md).
struct EngineTimes {
  double force_pass = 0.0;       // s: contacts and integration (the sweep and the parked pass)
  double first_half = 0.0;       // s: the first half step of each step() call, a sweep of its own
  double neighbour_build = 0.0;  // s: full rebuilds (spatial sort, neighbour list, share routing)
  double list_edit = 0.0;        // s: particles added to or removed from the lists without a rebuild
  // Of force_pass: the mean time a thread waited for the slowest in the pair pass and in
  // the parked pass (load imbalance between the row ranges).
  double pair_pass_idle = 0.0, parked_pass_idle = 0.0;
};

// Thrown when a run blows up; what() names particle id, step, overlap and likely cause.
class BlowUpError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Simulation {
 public:
  explicit Simulation(const SimulationConfig& config);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Materials and their pair interactions (particle-particle and particle-wall alike).
  // The engine starts with none. Every pair that can meet needs set_interaction() before
  // the particle or wall that makes it meet is added: add_particle and add_wall refuse a
  // pair without one (there is no default interaction).
  MaterialId add_material(const Material& m);
  void set_interaction(MaterialId a, MaterialId b, const PairInteraction& p);

  int add_wall(const Wall& w);  // returns the wall index
  std::size_t wall_count() const;
  const Wall& wall(int index) const;
  Vec3 wall_force(int index) const;  // total force particles exert on the wall, last step, N

  // Insert a particle (between steps); returns its stable id. Does not check overlap.
  std::int64_t add_particle(const ParticleInit& p);
  // Remove particles by id (between steps); unknown ids are ignored; returns how many went.
  std::size_t remove_particles(const std::vector<std::int64_t>& ids);
  // Remove every particle whose position satisfies pred(x); returns the removed ids.
  template <class Pred>
  std::vector<std::int64_t> remove_if(Pred pred) {
    std::vector<std::int64_t> gone;
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (pred(x_[i])) gone.push_back(id_[i]);
    remove_particles(gone);
    return gone;
  }
  // Overwrite the velocity and angular velocity of particle `index`.
  void set_velocity(std::size_t index, Vec3 v, Vec3 w);

  // Resolves dt (refuses an unstable one with std::invalid_argument naming value and
  // bound), builds lists and computes the initial forces. step() calls it when needed.
  void setup();
  // Advance n steps. Throws BlowUpError on blow-up.
  void step(std::int64_t n = 1);

  TimeStepAdvice time_step_advice() const;
  double dt() const;  // resolved after setup()
  double time() const { return time_; }
  std::int64_t step_count() const { return step_; }
  void set_threads(int n);
  int threads() const { return threads_; }
  const SimulationConfig& config() const { return cfg_; }

  // Particle state (structure of arrays; see the note on indices above).
  std::size_t size() const { return x_.size(); }
  const std::vector<std::int64_t>& ids() const { return id_; }
  const std::vector<Vec3>& positions() const { return x_; }
  const std::vector<Vec3>& velocities() const { return v_; }
  const std::vector<Vec3>& angular_velocities() const { return w_; }
  const std::vector<Vec3>& forces() const { return f_; }   // incl. gravity, last force pass
  const std::vector<Vec3>& torques() const { return t_; }
  const std::vector<double>& radii() const { return r_; }
  const std::vector<double>& masses() const { return m_; }
  const std::vector<int>& materials() const { return mat_; }
  const std::vector<Motion>& motions() const { return motion_; }
  std::ptrdiff_t index_of(std::int64_t id) const;  // -1 if absent (linear search)

  NeighbourStats neighbour_stats() const;
  const EngineTimes& times() const { return times_; }
  std::size_t memory_bytes() const;  // heap bytes held by particle, list and history arrays

  // Contact history with a wall (tests: history survives rebuilds/sorting).
  const ContactHistory& wall_history(std::size_t index, int wall) const;

  // Checkpoints (dem/simulation_state.hpp). The force sums depend on the particle order
  // and the neighbour list, both set at the last rebuild; so rebuild_lists() forces a
  // rebuild (spatial re-sort + list) now, between steps, and a run calls it right before
  // export_state(). import_state() ends with the same rebuild on the same particles in
  // the same order, so the resumed run continues bitwise identically to the run that
  // wrote the state (which, having rebuilt at that moment too, is the reference run).
  void rebuild_lists();
  SimulationState export_state() const;
  // Replaces every particle, contact history, the clock and the time step. The engine
  // must already hold the same materials, interactions and walls (as the scene builds
  // them from its config): a difference is refused with std::invalid_argument.
  void import_state(const SimulationState& s);
  // Contact histories for the particles added so far, before setup(): a film laid in from
  // an earlier run keeps its tangential and rolling springs loaded (a settled start,
  // dem/scene/settled_start.hpp) instead of slipping until they load again. Pairs and
  // walls by particle id; the first rebuild carries them into the list. Throws
  // std::invalid_argument after setup() or on an unknown id or wall.
  void preset_contact_histories(const std::vector<PairHistoryEntry>& pairs, const std::vector<WallHistoryEntry>& walls);
  // The per-particle arrays a state carries, in the engine's list order (below):
  // f(name, units, array). The checkpoint file stores each as /engine/<name>.
  template <class F>
  static void for_each_state_particle_array(SimulationState& s, F&& f) {
    for_each_stored_particle_array(
        [&](auto, auto stored, const char* name, const char* units, bool) { f(name, units, s.*stored); });
  }

 private:
  struct Impl;  // neighbour lists, histories, scratch
  void rebuild();
  void resolve_time_step();  // dt_ and the blow-up limit from the advice (setup's first half)
  // What compute_forces does to each particle once its force and torque are complete (at
  // the end of its row, or after the pass if it has parked shares): nothing (set-up), the
  // second half kick (last step of a step() call), or that kick and then the next step's
  // first half (kick, drift), saving two sweeps.
  enum class AfterForces : std::uint8_t { nothing, second_half, second_and_next_first_half };
  // Returns the two largest squared displacements since the last build after the next
  // step's first half (AfterForces::second_and_next_first_half), else zeros.
  ListSlack compute_forces(bool update_history, AfterForces after);
  ListSlack integrate_first_half();  // returns the two largest squared displacements since the last build
  FirstHalfStep begin_first_half();  // the constants of this step's first half
  bool scene_symmetric_about_drum() const;
  void invalidate_list();  // particles or walls changed: carry contacts, rebuild before the next step
  // Speed (dem/simulation_list_edits.cpp): particles added or removed while the list is
  // valid join or leave it without a rebuild.
  void take_in_new_particles();
  void remove_from_lists(const std::vector<std::int32_t>& order, const std::vector<std::int32_t>& new_of_old);
  std::uint32_t candidate_walls(std::size_t i) const;  // walls particle i may touch before the next rebuild
  double half_skin_of(std::size_t i) const;            // particle i's half-skin for a list built now (ListSlack)
  void permute_particles(const std::vector<std::int32_t>& order);
  void update_pair_constants();
  // Refuses material m if a pair it would meet (materials of particles present, walls) has
  // no interaction; then counts m as in use. `what` names the caller in the message.
  void require_interactions(int m, const char* what);
  // x: the particle's position when the blow-up was detected (the force pass may have moved it since).
  [[noreturn]] void report_blow_up(std::size_t i, Vec3 x, double overlap, const std::string& partner) const;

  SimulationConfig cfg_;
  int threads_ = 1;
  double dt_ = 0.0;
  double time_ = 0.0;
  std::int64_t step_ = 0;
  bool ready_ = false;      // set-up done and lists valid
  bool dirty_ = true;       // particles added/removed since the last rebuild
  double blowup_fraction_ = 0.05;
  EngineTimes times_;
  std::vector<std::pair<std::int64_t, std::int64_t>> insert_log_;  // (step, first id inserted)

  std::vector<Material> materials_;
  std::vector<PairInteraction> interactions_;  // n_mat x n_mat
  std::vector<char> interaction_set_;          // n_mat x n_mat: set_interaction() called
  std::vector<char> material_in_use_;          // n_mat: some particle has been made of it
  std::vector<PairConstants> pc_;              // n_mat x n_mat
  std::size_t n_mat_ = 0;

  std::vector<Wall> walls_;
  std::vector<Vec3> wall_force_;

  std::int64_t next_id_ = 0;
  // Per-particle arrays (structure of arrays, index order); each is named once in
  // for_each_particle_array below.
  std::vector<std::int64_t> id_;
  std::vector<Vec3> x_, v_, w_, f_, t_;
  std::vector<double> r_, m_, inv_m_, inv_inertia_;
  std::vector<int> mat_;
  std::vector<Motion> motion_;
  std::vector<ContactHistory> wall_hist_;  // one row of walls_.size() per particle

  // The registry of the per-particle arrays: each once, as f(engine array, its
  // SimulationState member or Derived{}, name, units, per_wall). add_particle grows every
  // array by one row, permute_particles (spatial re-sort, removal) reorders every array,
  // memory_bytes counts every array, export_state / import_state copy the stored ones
  // (and the checkpoint file writes them, for_each_state_particle_array) in this order;
  // derived arrays are recomputed from material and radius (set_mass_properties). A row
  // is one element, or walls_.size() elements where per_wall is true. A new per-particle
  // quantity is its member, one line here, and (if stored) its SimulationState member.
  // The force pass reads the arrays through plain pointers, never through this list.
  struct Derived {};
  template <class F>
  static void for_each_particle_array(F&& f) {
    f(&Simulation::id_, &SimulationState::id, "id", "1", false);
    f(&Simulation::mat_, &SimulationState::material, "material", "1", false);
    f(&Simulation::r_, &SimulationState::radius, "radius", "m", false);
    f(&Simulation::motion_, &SimulationState::motion, "motion", "1", false);
    f(&Simulation::x_, &SimulationState::x, "x", "m", false);
    f(&Simulation::v_, &SimulationState::v, "v", "m/s", false);
    f(&Simulation::w_, &SimulationState::w, "w", "rad/s", false);
    f(&Simulation::f_, &SimulationState::f, "f", "N", false);
    f(&Simulation::t_, &SimulationState::t, "t", "N m", false);
    f(&Simulation::wall_hist_, &SimulationState::wall_history, "wall_history", kContactHistoryUnits, true);
    f(&Simulation::m_, Derived{}, "mass", "kg", false);
    f(&Simulation::inv_m_, Derived{}, "inverse_mass", "1/kg", false);
    f(&Simulation::inv_inertia_, Derived{}, "inverse_inertia", "1/(kg m^2)", false);
  }
  template <class F>
  static void for_each_stored_particle_array(F&& f) {
    for_each_particle_array([&](auto array, auto stored, const char* name, const char* units, bool per_wall) {
      if constexpr (!std::is_same_v<decltype(stored), Derived>) f(array, stored, name, units, per_wall);
    });
  }
  std::size_t row_width(bool per_wall) const { return per_wall ? walls_.size() : 1; }
  void set_mass_properties(std::size_t i);  // m_, inv_m_, inv_inertia_ from mat_ and r_

  std::unique_ptr<Impl> impl_;
};

}  // namespace centrec::dem
