// The theta convention of dem/film/drum_frame.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem/film/drum_frame.hpp"

using namespace centrec::film;

TEST(DrumFrame, DefaultIsThePapersView) {
  // Gravity along -y, drum turning clockwise seen from +z (omega_z < 0): theta is the
  // ordinary polar angle, 90 deg at the top.
  const DrumFrame f = DrumFrame::from_gravity(0.06, 0.171, 0.0, -6.94, -16.8);
  const DrumFrame def;
  for (double deg : {0.0, 45.0, 90.0, 135.0, 200.0, 359.0}) {
    const double a = deg * M_PI / 180.0;
    EXPECT_NEAR(f.theta(std::cos(a), std::sin(a)), a, 1e-12) << deg;
    EXPECT_NEAR(def.theta(std::cos(a), std::sin(a)), a, 1e-12) << deg;
  }
  EXPECT_NEAR(f.theta(0.0, 1.0), M_PI / 2, 1e-12);   // top
  EXPECT_NEAR(f.theta(0.0, -1.0), 1.5 * M_PI, 1e-12);  // bottom
  EXPECT_NEAR(f.wall_distance(0.03, 0.04), 0.01, 1e-15);
}

TEST(DrumFrame, ThetaRunsAgainstTheRotationWithTheTopAtNinety) {
  // Any gravity direction and either rotation sense: the top is at 90 deg and a point
  // carried by the wall (rotated by +eps in the sense of omega) moves to smaller theta.
  int checked = 0;
  for (double gdir : {-2.0, -0.5, 0.3, 1.9, 3.0})
    for (double om : {-12.0, 7.0}) {
      const DrumFrame f = DrumFrame::from_gravity(0.1, 0.2, std::cos(gdir), std::sin(gdir), om);
      EXPECT_NEAR(f.theta(-std::cos(gdir), -std::sin(gdir)), M_PI / 2, 1e-12);
      for (double phi = 0.1; phi < 6.2; phi += 0.7) {
        const double eps = 1e-3 * (om > 0 ? 1 : -1);
        const double t0 = f.theta(std::cos(phi), std::sin(phi));
        const double t1 = f.theta(std::cos(phi + eps), std::sin(phi + eps));
        EXPECT_NEAR(wrap_angle(t0 - t1), 1e-3, 1e-9);
        ++checked;
      }
    }
  std::printf("theta convention checked at %d points (5 gravity directions x 2 rotation senses)\n", checked);
}

TEST(DrumFrame, RejectsUndefinedTop) {
  EXPECT_THROW(DrumFrame::from_gravity(0.1, 0.2, 0.0, 0.0, 5.0), std::invalid_argument);
  EXPECT_THROW(DrumFrame::from_gravity(0.1, 0.2, 0.0, -1.0, 0.0), std::invalid_argument);
}
