#include "bench/centrec_run.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "dem/simulation.hpp"
#include "bench/film_summary.hpp"
#include "bench/process_memory.hpp"

namespace centrec::bench {
namespace {

using dem::Vec3;

FilmSummary summarize(const FilmCase& c, const dem::Simulation& sim) {
  const std::size_t n = sim.size();
  std::vector<double> x(3 * n), v(3 * n), w(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = sim.positions()[i], u = sim.velocities()[i], o = sim.angular_velocities()[i];
    x[3 * i] = p.x, x[3 * i + 1] = p.y, x[3 * i + 2] = p.z;
    v[3 * i] = u.x, v[3 * i + 1] = u.y, v[3 * i + 2] = u.z;
    w[3 * i] = o.x, w[3 * i + 1] = o.y, w[3 * i + 2] = o.z;
  }
  const double r = c.radius();
  const double mass = c.density * 4.0 / 3.0 * M_PI * r * r * r;
  FilmSummary s = summarize_film(c, static_cast<long>(n), x.data(), v.data(), w.data(), mass, 0.4 * mass * r * r);
  s.pair_contacts = static_cast<double>(sim.neighbour_stats().pair_contacts);
  return s;
}

dem::SimulationConfig make_config(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r) {
  dem::SimulationConfig cfg;
  cfg.gravity = {0.0, c.gravity_y(), c.gravity_z()};
  cfg.dt = c.dt;
  cfg.skin_fraction = r.skin_fraction;
  cfg.periodic_z = true;
  cfg.z_lo = 0.0;
  cfg.z_hi = s.length;
  cfg.drum = {{0, 0, 0}, {0, 0, 1}, c.omega()};
  // LIGGGHTS' mesh walls give the rolling model the particle's absolute spin (docs/dem_physics.md): use the same form so both engines compute the same torques.
  cfg.wall_rolling = dem::WallRolling::liggghts;
  cfg.threads = r.threads;
  return cfg;
}

}  // namespace

struct CentrecFilmRun::State {
  FilmCase c;
  CentrecRunSettings r;
  EngineResult res;
  std::unique_ptr<dem::Simulation> sim;
  std::size_t rebuilds_timed = 0;  // list rebuilds inside the timed phases
  int phase_in_window = 0;
  dem::SimulationState settled;    // start of every window (only kept if r.replays > 1)
  void fail(const std::exception& e) {  // keeps what was timed; later phases do nothing
    res.note = std::string("centrec failed: ") + e.what();
    sim.reset();
  }
};

CentrecFilmRun::CentrecFilmRun(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r)
    : st_(std::make_unique<State>()) {
  st_->c = c;
  st_->r = r;
  EngineResult& res = st_->res;
  res.engine = "centrec";
  res.workers = r.threads;
  res.particles = static_cast<long>(s.particles.size());
  res.steps = r.timed_steps;
  try {
    const std::size_t rss0 = resident_bytes();
    st_->sim = std::make_unique<dem::Simulation>(make_config(c, s, r));
    dem::Simulation& sim = *st_->sim;
    // Particles and the wall as two materials (same E, nu; per-pair e, mu, mu_r), as the
    // deck's atom types 1 and 2.
    const dem::MaterialId grain = sim.add_material({c.youngs_modulus, c.poisson_ratio, c.density});
    const dem::MaterialId wall_mat = sim.add_material({c.youngs_modulus, c.poisson_ratio, c.density});
    sim.set_interaction(grain, grain, c.pair_interaction());
    sim.set_interaction(grain, wall_mat, c.wall_interaction());
    sim.add_wall(dem::Wall::cylinder({0, 0, 0}, {0, 0, 1}, c.drum_radius, -INFINITY, INFINITY, c.omega(), wall_mat));
    for (const auto& p : s.particles) {
      sim.add_particle({grain, 0.5 * s.diameter, {p.x[0], p.x[1], p.x[2]}, {p.v[0], p.v[1], p.v[2]},
                        {p.w[0], p.w[1], p.w[2]}});
    }
    sim.setup();
    sim.step(r.settle_steps);
    res.settled = summarize(c, sim);
    res.bytes_per_particle = static_cast<double>(sim.memory_bytes()) / res.particles;
    const std::size_t rss1 = resident_bytes();
    if (rss1 > rss0) res.rss_bytes_per_particle = static_cast<double>(rss1 - rss0) / res.particles;
    // A rebuild at the window's start (untimed) makes the first window run exactly as
    // every replay does after import_state, which ends with the same rebuild.
    sim.rebuild_lists();
    if (r.replays > 1) st_->settled = sim.export_state();
  } catch (const std::exception& e) {
    st_->fail(e);
  }
}

CentrecFilmRun::~CentrecFilmRun() = default;

void CentrecFilmRun::time_phase() {
  if (!st_->sim) return;
  try {
    if (st_->phase_in_window == st_->r.repeats) {
      st_->sim->import_state(st_->settled);
      st_->phase_in_window = 0;
    }
    const std::size_t rebuilds = st_->sim->neighbour_stats().rebuilds;
    const auto t0 = std::chrono::steady_clock::now();
    st_->sim->step(st_->r.timed_steps);
    const auto t1 = std::chrono::steady_clock::now();
    st_->rebuilds_timed += st_->sim->neighbour_stats().rebuilds - rebuilds;
    st_->res.seconds.push_back(std::chrono::duration<double>(t1 - t0).count());
    ++st_->phase_in_window;
  } catch (const std::exception& e) {
    st_->fail(e);
  }
}

EngineResult CentrecFilmRun::finish() {
  EngineResult& res = st_->res;
  if (!st_->sim || res.seconds.empty()) return res;
  const dem::Simulation& sim = *st_->sim;
  res.final = summarize(st_->c, sim);
  const dem::NeighbourStats ns = sim.neighbour_stats();
  // NeighbourStats::list_entries holds each pair once (half list), as LIGGGHTS' count.
  res.list_pairs_per_particle = static_cast<double>(ns.list_entries) / res.particles;
  res.rebuilds_per_phase =
      static_cast<double>(st_->rebuilds_timed) / static_cast<double>(res.seconds.size());
  res.ok = res.final.atoms == res.particles;
  if (!res.ok) res.note = "centrec lost particles";
  return res;
}

EngineResult run_centrec(const FilmCase& c, const FilmState& s, const CentrecRunSettings& r) {
  CentrecFilmRun run(c, s, r);
  for (int k = 0; k < r.replays * r.repeats; ++k) run.time_phase();
  return run.finish();
}

}  // namespace centrec::bench
