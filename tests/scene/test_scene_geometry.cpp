// Scene set-up: the rough-wall lattice touches the wall without overlaps, tiles a
// periodic slice, and the packed start co-rotates rigidly inside the drum.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/packed_film.hpp"
#include "dem/scene/wall_lattice.hpp"

using namespace centrec::dem;
using namespace centrec::dem::scene;

TEST(SceneGeometry, RoughWallLatticesTouchWallWithoutOverlap) {
  for (Lattice lat : {Lattice::square, Lattice::hexagonal}) {
    RoughWallSpec spec;
    spec.enabled = true;
    spec.lattice = lat;
    spec.sphere_diameter = 1.2e-3;
    spec.spacing = 1.3e-3;
    const double R = 0.02, Lz = 12e-3;
    auto c = rough_wall_centres(spec, R, 0.0, Lz, true);
    ASSERT_GT(c.size(), 100u);
    double min_d = 1e9;
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(std::hypot(c[i].x, c[i].y), R - 0.6e-3, 1e-12);
      for (std::size_t j = i + 1; j < c.size(); ++j) {
        Vec3 d = c[i] - c[j];
        d.z -= Lz * std::round(d.z / Lz);  // periodic image
        min_d = std::min(min_d, norm(d));
      }
    }
    std::printf("%s lattice: %zu spheres, closest centres %.4f mm (sphere 1.2 mm)\n",
                lat == Lattice::square ? "square" : "hexagonal", c.size(), min_d * 1e3);
    EXPECT_GE(min_d, 1.2e-3 * (1 - 1e-9));
    EXPECT_LE(min_d, 1.3e-3 * 1.05);  // chord spacing close to the asked spacing
  }
}

TEST(SceneGeometry, PackedStartFitsInsideAndCoRotates) {
  SceneConfig c;
  c.drum.diameter = 0.04;
  c.slice.enabled = true;
  c.slice.length = 10 * c.particle.diameter;
  c.initial_film.particles = 3000;
  c.threads = 1;
  CentrecScene s(c);
  const auto& sim = s.simulation();
  ASSERT_EQ(sim.size(), 3000u);
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const Vec3 x = sim.positions()[i];
    EXPECT_LE(std::hypot(x.x, x.y) + sim.radii()[i], 0.02 + 1e-12);
    const Vec3 v_rigid = cross(Vec3{0, 0, c.drum.omega}, x);
    EXPECT_LT(norm(sim.velocities()[i] - v_rigid), 1e-9);
  }
}

TEST(SceneGeometry, RejectsBadDrum) {
  SceneConfig c;
  c.drum.diameter = 0.01;  // < 20 d
  EXPECT_THROW(CentrecScene s(c), std::invalid_argument);
}
