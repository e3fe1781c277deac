// Every particle the scene creates (glued rough wall, pre-filled film, feeder) is made of
// the case's particle material and meets the drum wall with the case's particle-wall
// interaction. The case sets every parameter away from the paper's Table 1, so a particle
// left with any built-in default (density, E, nu, restitution, friction, rolling
// friction) is caught, and so is a fed mass booked with another density than the one the
// engine integrates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem/scene/centrec_scene.hpp"
#include "dem/sphere_mass.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

namespace {

// A small drum at Froude number omega^2 R / g = 4 whose materials and interactions all
// differ from Table 1. Particle-wall friction 10000 and rolling friction 0.6: a particle
// on the smooth wall cannot slide, and the largest tangential-to-normal load it meets here
// (about 0.3: gravity against the centrifugal force) cannot roll it either.
SceneConfig odd_materials_drum() {
  SceneConfig c;
  c.particle.material = Material{2.0e7, 0.25, 2500.0};
  c.wall_material = Material{3.0e7, 0.2, 7800.0};
  c.particle_particle = PairInteraction{0.6, 0.5, 0.1};
  c.particle_wall = PairInteraction{0.3, 10000.0, 0.6};
  c.drum.diameter = 0.03;
  c.drum.length = 0.02;
  c.drum.tilt = M_PI / 4;
  c.drum.omega = std::sqrt(4.0 * 9.81 / 0.015);
  c.drum.back_plate = true;
  c.feeder.mass_flow = 2.0e-3;
  c.feeder.radial_offset = 6e-3;
  c.feeder.axial_start = 2e-3;
  c.feeder.axial_length = 5e-3;
  c.dt = 1e-5;
  // A wide blow-up margin, so that particles of a wrong material (the engine's former
  // built-in one was softer and denser) fail these checks rather than the overlap limit.
  c.max_impact_speed = 5.0;
  c.threads = 1;
  return c;
}

bool same_material(const Material& a, const Material& b) {
  return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio && a.density == b.density;
}
bool same_interaction(const PairInteraction& a, const PairInteraction& b) {
  return a.restitution == b.restitution && a.friction == b.friction && a.rolling_friction == b.rolling_friction;
}

// Particles touching the drum wall, and how many of them do not slide on it: the sphere's
// surface at the contact point moves with the wall within 0.1 % of omega R. Free
// particles only.
struct WallRiders {
  int touching = 0;
  int riding = 0;
  double fraction() const { return touching ? static_cast<double>(riding) / touching : 0.0; }
};
WallRiders wall_riders(const CentrecScene& s) {
  const Simulation& sim = s.simulation();
  const double R = s.drum_radius(), om = s.config().drum.omega;
  WallRiders w;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (sim.motions()[i] != Motion::free) continue;
    const Vec3 x = sim.positions()[i];
    const double r = sim.radii()[i];
    if (std::hypot(x.x, x.y) + r < R - 0.02 * r) continue;  // not in contact with the cylinder
    const Vec3 u = Vec3{x.x, x.y, 0.0} * (1.0 / std::hypot(x.x, x.y));  // towards the wall
    const Vec3 slip = sim.velocities()[i] + cross(sim.angular_velocities()[i], r * u) - cross(Vec3{0, 0, om}, x + r * u);
    ++w.touching;
    w.riding += norm(slip) < 1e-3 * om * R;
  }
  return w;
}

}  // namespace

TEST(FedMaterial, EveryParticleCarriesTheCaseMaterial) {
  SceneConfig c = odd_materials_drum();
  c.rough_wall.enabled = true;
  c.rough_wall.spacing = 1.5e-3;
  c.initial_film.particles = 150;
  CentrecScene s(c);
  s.advance(0.01);
  const Simulation& sim = s.simulation();
  const SimulationState st = sim.export_state();
  const std::size_t n_mat = st.materials.size();
  const std::int64_t fed = s.feeder_stats().inserted;
  ASSERT_GT(fed, 5);
  int glued = 0, wrong_material = 0, wrong_wall_interaction = 0, wrong_pair_interaction = 0;
  const int wall_mat = sim.wall(0).material;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const auto m = static_cast<std::size_t>(sim.materials()[i]);
    glued += sim.motions()[i] == Motion::drum;
    wrong_material += !same_material(st.materials[m], c.particle.material);
    wrong_wall_interaction +=
        !same_interaction(st.interactions[m * n_mat + static_cast<std::size_t>(wall_mat)], c.particle_wall);
    wrong_pair_interaction += !same_interaction(st.interactions[m * n_mat + m], c.particle_particle);
  }
  std::printf("particles %zu (glued %d, pre-filled %lld, fed %lld): wrong material %d, wrong particle-wall %d, "
              "wrong particle-particle %d\n",
              sim.size(), glued, static_cast<long long>(c.initial_film.particles), static_cast<long long>(fed),
              wrong_material, wrong_wall_interaction, wrong_pair_interaction);
  EXPECT_GT(glued, 0);
  EXPECT_EQ(wrong_material, 0);
  EXPECT_EQ(wrong_wall_interaction, 0);
  EXPECT_EQ(wrong_pair_interaction, 0);
  EXPECT_TRUE(same_material(st.materials[static_cast<std::size_t>(wall_mat)], c.wall_material));
}

TEST(FedMaterial, FedMassBookedEqualsEngineMass) {
  SceneConfig c = odd_materials_drum();
  c.initial_film.particles = 100;
  CentrecScene s(c);
  const std::int64_t first_fed_id = c.initial_film.particles;  // the pre-fill takes ids 0..N-1
  s.advance(0.02);
  const Simulation& sim = s.simulation();
  double engine_mass = 0.0, case_mass = 0.0;
  std::int64_t n = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (sim.ids()[i] < first_fed_id) continue;
    engine_mass += sim.masses()[i];
    case_mass += sphere_mass(c.particle.material.density, sim.radii()[i]);
    ++n;
  }
  const double booked = s.feeder_stats().inserted_mass;
  std::printf("fed %lld particles: booked %.6e kg, engine %.6e kg (case density %.6e kg), relative %.2e\n",
              static_cast<long long>(n), booked, engine_mass, case_mass, engine_mass / booked - 1.0);
  ASSERT_EQ(n, s.feeder_stats().inserted);  // none left the drum yet
  EXPECT_NEAR(engine_mass / booked, 1.0, 1e-12);
  EXPECT_NEAR(case_mass / booked, 1.0, 1e-12);
}

// A fed particle that reaches the smooth wall rides with it, as a pre-filled one does.
// Measured after 0.1 s (0.8 turn). With a rolling friction of 1-2 the pre-filled layer
// itself starts to slip after about half a turn: EPSD2's rolling torque is kept in the
// fixed frame while the contact turns with the drum (as in LIGGGHTS 3.8), so it becomes
// a torque about the contact normal that spins the sphere up.
TEST(FedMaterial, FedParticleStopsSlidingOnTheWallAsAPrefilledOne) {
  SceneConfig fed_case = odd_materials_drum();
  CentrecScene fed(fed_case);
  fed.advance(0.1);
  const WallRiders f = wall_riders(fed);

  SceneConfig pre_case = odd_materials_drum();
  pre_case.feeder.enabled = false;
  pre_case.initial_film.particles = 200;
  CentrecScene pre(pre_case);
  pre.advance(0.1);
  const WallRiders p = wall_riders(pre);

  const std::int64_t inserted = fed.feeder_stats().inserted;
  std::printf("after 0.1 s: fed %lld, %d on the wall, %.1f %% of them not sliding; pre-filled %d on the wall, "
              "%.1f %% not sliding\n",
              static_cast<long long>(inserted), f.touching, 100.0 * f.fraction(), p.touching, 100.0 * p.fraction());
  EXPECT_EQ(p.touching, pre_case.initial_film.particles);
  EXPECT_GE(p.fraction(), 0.98);
  EXPECT_GT(f.touching, inserted / 2);  // the rest sit on them or are still in flight
  EXPECT_GT(f.fraction(), 0.9);
}
