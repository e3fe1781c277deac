// A minimal drum through the DEM engine's API (dem/simulation.hpp; docs/dem_physics.md).
//
// Rings of particles lie on the inside of a drum spinning about the z axis, well above the
// speed at which the film centrifuges (Froude number omega^2 R / g = 3.8). They start at 70 %
// of the drum's speed, as fed particles arrive (still above Froude 1, so they stay on the
// wall); the wall's friction drags them up to the drum's speed. The program checks that,
// after 0.1 s, the particles co-rotate with the drum (mean angular velocity about the axis
// within 1 % of omega), that every particle is still on the wall (gap below 1 % of its
// diameter), and that no particle and no mass was lost.
// It prints one line per check and exits with 1 if one fails.
//
// Build: part of the default build (build/apps/examples/example_drum); ctest runs it
// (test example_drum, label default).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dem/simulation.hpp"

using namespace centrec::dem;

int main() {
  // 1. Configure the engine: gravity across the axis, the drum's rigid rotation, a domain
  //    periodic along z (no end walls), and the time step (0 would take the advisor's).
  const double R = 0.015;                         // drum radius, m
  const double omega = 50.0;                      // rad/s (477 rpm): omega^2 R / g = 3.8
  const double radius = 0.6e-3;                   // particle radius, m (d = 1.2 mm)
  const int around = 70, rows = 4;                // particles round the drum, axial rows
  const double length = rows * 2.5 * radius;      // periodic length, m
  SimulationConfig cfg;
  cfg.gravity = {0.0, -9.81, 0.0};
  cfg.drum.omega = omega;  // carries Motion::drum particles (none here) and defines the drum frame
  cfg.periodic_z = true;
  cfg.z_lo = 0.0;
  cfg.z_hi = length;
  cfg.dt = 2e-5;  // s, below the stability bound (printed below with the advised value)
  cfg.verbose = false;
  Simulation sim(cfg);

  // 2. Materials and their interactions. The engine has no default: every pair that can
  //    meet (particle-particle, particle-wall) needs set_interaction before it can meet.
  const MaterialId grain = sim.add_material(Material{5e6, 0.3, 3560.0});  // E, nu, rho (paper Table 1)
  const MaterialId steel = sim.add_material(Material{5e6, 0.3, 3560.0});
  sim.set_interaction(grain, grain, PairInteraction{0.46, 0.81, 0.26});     // e, mu, mu_r
  sim.set_interaction(grain, steel, PairInteraction{0.46, 10000.0, 0.26});  // a wall that does not slip

  // 3. The drum: the inside of a cylinder about z, spinning at omega.
  const int drum = sim.add_wall(Wall::cylinder({0, 0, 0}, {0, 0, 1}, R, -1.0, 1.0, omega, steel));

  // 4. Particles: one ring per axial row, each touching the wall, moving at 70 % of the
  //    drum's speed. add_particle returns a stable id (indices change at every re-sort).
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < around; ++k) {
      const double phi = 2.0 * M_PI * (k + 0.5 * row) / around, rho = R - radius;
      const Vec3 x{rho * std::cos(phi), rho * std::sin(phi), (row + 0.5) * 2.5 * radius};
      const Vec3 v{-0.7 * omega * x.y, 0.7 * omega * x.x, 0.0};
      sim.add_particle(ParticleInit(grain, radius, x, v));
    }
  double mass0 = 0.0;
  for (double m : sim.masses()) mass0 += m;

  // 5. Run. The first step() sets up (time step, neighbour lists, first forces).
  const std::int64_t steps = 5000;
  sim.step(steps);
  const TimeStepAdvice advice = sim.time_step_advice();
  std::printf("drum: %zu particles, dt = %.3g s (advised %.3g s, stable below %.3g s), %lld steps = %.3f s = %.2f "
              "turns\n",
              sim.size(), sim.dt(), advice.recommended, advice.stable_bound, static_cast<long long>(steps), sim.time(),
              sim.time() * omega / (2.0 * M_PI));

  // 6. Read the state back (structure of arrays) and check the physics.
  double omega_sum = 0.0, gap_max = 0.0, mass = 0.0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const Vec3 x = sim.positions()[i], v = sim.velocities()[i];
    const double rho2 = x.x * x.x + x.y * x.y;
    omega_sum += (x.x * v.y - x.y * v.x) / rho2;  // angular velocity about z
    gap_max = std::max(gap_max, R - std::sqrt(rho2) - radius);
    mass += sim.masses()[i];
  }
  const double ratio = omega_sum / static_cast<double>(sim.size()) / omega;
  const Vec3 load = sim.wall_force(drum);
  const bool co_rotating = std::fabs(ratio - 1.0) < 0.01;
  const bool on_wall = gap_max < 0.01 * 2.0 * radius;
  // (The arrays are re-sorted as the run goes: the sum may differ in the last bits.)
  const bool mass_kept = sim.size() == static_cast<std::size_t>(around * rows) && std::fabs(mass - mass0) <= 1e-12 * mass0;
  std::printf("mean angular velocity / drum omega = %.4f (expected 1 within 0.01): %s\n", ratio,
              co_rotating ? "co-rotating" : "NOT co-rotating");
  std::printf("largest gap between a particle and the wall = %.3g m (expected < %.3g m): %s\n", gap_max,
              0.01 * 2.0 * radius,
              on_wall ? "all on the wall" : "NOT all on the wall");
  std::printf("particle mass %.6g kg at the start, %.6g kg at the end: %s\n", mass0, mass,
              mass_kept ? "kept" : "NOT kept");
  std::printf("force of the particles on the drum: (%.3g, %.3g, %.3g) N (their weight: %.3g N along -y)\n", load.x,
              load.y, load.z, mass * 9.81);
  return co_rotating && on_wall && mass_kept ? 0 : 1;
}
