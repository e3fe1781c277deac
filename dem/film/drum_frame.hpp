#pragma once
// Where a particle sits in the drum cross-section: its wall distance and its angle theta.
//
// Theta convention (docs/film_sampling.md; paper Figs 1b, 4, 5). The paper draws the drum
// rotating clockwise and measures its sections at 45, 90 and 135 deg counter-clockwise,
// i.e. AGAINST the rotation, and places all three in the moving zone. The moving zone
// is around the top of the cross-section, where the wall-normal load omega^2 R - g cos(beta)
// is smallest (docs/centrec_scene.md), so here:
//
//   theta increases against the drum's rotation, and
//   theta = theta_of_top (default 90 deg) at the "top": the direction opposite to the
//   transverse (x-y) component of gravity.
//
// So theta = 0 is the horizontal side the wall reaches just after passing the top, and
// the wall carries material through 135 -> 90 -> 45 deg. The 45/90/135 deg sections
// lie symmetrically about the top. The paper does not state its reference direction;
// this is the reading that puts its sections in the moving zone, and theta_of_top is a
// parameter so another reading is one number away.
#include <cmath>

namespace centrec::film {

struct DrumFrame {
  double radius = 0.0;   // m, wall radius R = D/2
  double length = 0.0;   // m, L (inlet z = 0, outlet z = L)
  // Polar angle atan2(y, x) of the top (opposite to gravity's x-y component).
  double top_polar_angle = M_PI / 2.0;
  // +1 if the drum rotates right-handed about +z (omega_z > 0), -1 otherwise.
  int rotation_sign = -1;
  // Theta assigned to the top, rad.
  double theta_of_top = M_PI / 2.0;

  // Frame from the simulation's gravity vector and angular velocity (drum frame).
  // Throws std::invalid_argument if gravity has no x-y component (top undefined) or
  // omega_z == 0 (direction undefined).
  static DrumFrame from_gravity(double radius, double length, double gx, double gy, double omega_z,
                                double theta_of_top = M_PI / 2.0);

  // Theta in [0, 2 pi) of the point (x, y).
  double theta(double x, double y) const;
  // Wall distance of a point (particle centre): R - sqrt(x^2 + y^2), m.
  double wall_distance(double x, double y) const { return radius - std::hypot(x, y); }
};

// a wrapped into [0, 2 pi).
double wrap_angle(double a);

}  // namespace centrec::film
