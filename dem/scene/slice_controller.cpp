#include "dem/scene/slice_controller.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "dem/scene/rng_state.hpp"

namespace centrec::dem::scene {

double slice_axial_mass_flow(const Simulation& sim, double slice_length) {
  double p = 0.0;
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (sim.motions()[i] == Motion::free) p += sim.masses()[i] * sim.velocities()[i].z;
  return p / slice_length;
}

SliceHoldupController::SliceHoldupController(const SceneConfig& config, MaterialId particle_material, double start_time)
    : cfg_(config),
      material_(particle_material),
      window_(config.slice.controller_window_turns * 2.0 * M_PI / std::fabs(config.drum.omega)),
      sizes_(config.particle, config.seed + 7),
      rng_(config.seed ^ 0x5851f42d4c957f2dULL) {
  if (!(config.slice.enabled && config.slice.target_mass_flow > 0.0))
    throw std::invalid_argument("slice holdup controller: needs slice mode and slice.target_mass_flow > 0");
  state_.window_start = start_time;
}

void SliceHoldupController::after_batch(Simulation& sim) {
  state_.flow_sum += slice_axial_mass_flow(sim, cfg_.slice.length);
  ++state_.flow_samples;
  if (sim.time() - state_.window_start < window_ - 0.5 * sim.dt()) return;
  const double mdot = state_.flow_sum / static_cast<double>(state_.flow_samples);
  std::int64_t n = 0;
  for (Motion m : sim.motions()) n += (m == Motion::free);
  const SliceSpec& s = cfg_.slice;
  // Log error: mdot rises steeply with the holdup (about N^4 in a thin slice), so a
  // relative change of N in proportion to ln(target / mdot) is a Newton step when
  // gain ~ 1 / (d ln mdot / d ln N); a stalled film (mdot <= 0) asks for the largest step.
  const double error = mdot > 0.0 ? std::log(s.target_mass_flow / mdot) : 10.0;
  const double limit = s.controller_max_step * static_cast<double>(n);
  const auto change = static_cast<std::int64_t>(std::llround(std::clamp(s.controller_gain * error * n, -limit, limit)));
  std::int64_t done = 0;
  if (change > 0) done = insert(sim, change);
  if (change < 0) done = -remove_surface(sim, -change);
  state_.log.push_back({sim.time(), mdot, n + done, done});
  state_.window_start = sim.time();
  state_.flow_sum = 0.0;
  state_.flow_samples = 0;
}

std::int64_t SliceHoldupController::insert(Simulation& sim, std::int64_t count) {
  const double R = 0.5 * cfg_.drum.diameter, Ls = cfg_.slice.length, om = cfg_.drum.omega;
  const double dmax = sizes_.max_diameter();
  struct Near {
    Vec3 x;
    double r;
    double vz;
    bool free;
  };
  std::vector<Near> all;
  for (std::size_t i = 0; i < sim.size(); ++i)
    all.push_back({sim.positions()[i], sim.radii()[i], sim.velocities()[i].z, sim.motions()[i] == Motion::free});
  auto dz_image = [&](double dz) { return dz - Ls * std::round(dz / Ls); };
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::int64_t added = 0;
  for (std::int64_t k = 0; k < count; ++k) {
    const double radius = 0.5 * sizes_.next_diameter();
    bool placed = false;
    for (int attempt = 0; attempt < 200 && !placed; ++attempt) {
      const double th = 2.0 * M_PI * u01(rng_), z = Ls * u01(rng_);
      const Vec3 dir{std::cos(th), std::sin(th), 0.0};
      // Local film surface: the innermost particle edge within 2 d of this spot.
      double surface = R, vz_sum = 0.0;
      int vz_n = 0;
      for (const Near& p : all) {
        const double rho = std::hypot(p.x.x, p.x.y);
        // The patch is an angle (arc 2 d at the wall), not a width at each particle's own
        // radius: else a particle near the axis would sit in every patch.
        const double arc = R * std::fabs(std::remainder(std::atan2(p.x.y, p.x.x) - th, 2.0 * M_PI));
        if (arc > 2.0 * dmax || std::fabs(dz_image(p.x.z - z)) > 2.0 * dmax) continue;
        surface = std::min(surface, rho - p.r);
        if (p.free) {
          vz_sum += p.vz;
          ++vz_n;
        }
      }
      const double rho = surface - radius - 0.01 * radius;
      if (rho < 2.0 * radius) continue;  // the drum is full to the axis here
      const Vec3 x{rho * dir.x, rho * dir.y, z};
      bool clear = true;
      for (const Near& p : all) {
        Vec3 d = x - p.x;
        d.z = dz_image(d.z);
        const double s = radius + p.r;
        if (norm2(d) < s * s) {
          clear = false;
          break;
        }
      }
      if (!clear) continue;
      // Co-rotating with the drum, moving along z with its neighbours.
      const double vz = vz_n ? vz_sum / vz_n : 0.0;
      sim.add_particle({material_, radius, x, Vec3{-om * x.y, om * x.x, vz}, {0.0, 0.0, om}});
      all.push_back({x, radius, vz, true});
      placed = true;
      ++added;
    }
    if (!placed) break;  // no room found: try again next window
  }
  return added;
}

std::int64_t SliceHoldupController::remove_surface(Simulation& sim, std::int64_t count) {
  // Free particles ordered by the radius of their inner edge: the free surface first.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (sim.motions()[i] == Motion::free) order.push_back(i);
  auto inner = [&](std::size_t i) { return std::hypot(sim.positions()[i].x, sim.positions()[i].y) - sim.radii()[i]; };
  const auto k = static_cast<std::size_t>(std::min<std::int64_t>(count, static_cast<std::int64_t>(order.size())));
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](std::size_t a, std::size_t b) { return inner(a) < inner(b) || (inner(a) == inner(b) && a < b); });
  std::vector<std::int64_t> ids;
  for (std::size_t j = 0; j < k; ++j) ids.push_back(sim.ids()[order[j]]);
  return static_cast<std::int64_t>(sim.remove_particles(ids));
}

SliceControllerState SliceHoldupController::state() const {
  SliceControllerState s = state_;
  s.rng = rng_text(rng_);
  s.size_rng = sizes_.rng_state();
  return s;
}

void SliceHoldupController::restore(const SliceControllerState& s) {
  state_ = s;
  read_rng_text(s.rng, rng_, "slice controller");
  sizes_.set_rng_state(s.size_rng);
}

}  // namespace centrec::dem::scene
