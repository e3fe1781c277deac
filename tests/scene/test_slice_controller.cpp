// Slice holdup controller (dem/scene/slice_controller.hpp): its actuators insert without
// overlap and remove the free surface (convergence: test_slice_controller_converges.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/scene/centrec_scene.hpp"
#include "tests/scene/slice_case.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

namespace {

// Smallest surface gap between a particle with id >= first_new and any other particle.
double min_gap(const Simulation& sim, double period, std::int64_t first_new) {
  double worst = 1e9;
  for (std::size_t i = 0; i < sim.size(); ++i)
    for (std::size_t j = i + 1; j < sim.size(); ++j) {
      if (sim.ids()[i] < first_new && sim.ids()[j] < first_new) continue;
      Vec3 d = sim.positions()[i] - sim.positions()[j];
      d.z -= period * std::round(d.z / period);
      worst = std::min(worst, norm(d) - sim.radii()[i] - sim.radii()[j]);
    }
  return worst;
}

double inner_edge(const Simulation& sim, std::size_t i) {
  return std::hypot(sim.positions()[i].x, sim.positions()[i].y) - sim.radii()[i];
}

}  // namespace

TEST(SliceController, ActuatorsInsertWithoutOverlapAndRemoveTheSurface) {
  CentrecScene scene(centrec::testing::controlled_slice(600, 1e-3));
  auto& sim = scene.simulation();
  scene.advance(0.02);
  const double period = scene.config().slice.length, d = scene.config().particle.diameter;
  SliceHoldupController ctl(scene.config(), scene.particle_material(), sim.time());
  const std::int64_t before = scene.free_particles();
  std::int64_t first_new = 0;
  for (std::int64_t id : sim.ids()) first_new = std::max(first_new, id + 1);
  EXPECT_EQ(ctl.insert(sim, 60), 60);
  EXPECT_EQ(scene.free_particles(), before + 60);
  const double gap = min_gap(sim, period, first_new);
  std::printf("after inserting 60: smallest surface gap %.3g d\n", gap / d);
  EXPECT_GE(gap, -1e-12);
  sim.step(200);  // the inserted particles settle without blowing up

  // Removal takes the particles nearest the axis.
  double deepest_removed = 0.0;
  {
    std::vector<double> edges;
    for (std::size_t i = 0; i < sim.size(); ++i)
      if (sim.motions()[i] == Motion::free) edges.push_back(inner_edge(sim, i));
    std::sort(edges.begin(), edges.end());
    deepest_removed = edges[39];
  }
  EXPECT_EQ(ctl.remove_surface(sim, 40), 40);
  double innermost_left = 1e9;
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (sim.motions()[i] == Motion::free) innermost_left = std::min(innermost_left, inner_edge(sim, i));
  EXPECT_GE(innermost_left, deepest_removed);

  // A restored controller continues the same random sequence.
  SliceHoldupController a(scene.config(), scene.particle_material(), 0.0), b(scene.config(), scene.particle_material(), 0.0);
  b.restore(a.state());
  EXPECT_EQ(a.state().rng, b.state().rng);
}
