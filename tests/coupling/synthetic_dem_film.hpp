#pragma once
// A synthetic DEM film (what dem.h5 /film holds) with known answers: uniform thickness,
// the paper's profile (u = 0 below 1 d, linear to the surface), uniform solid fraction.
#include <cmath>

#include "coupling/dem_film_averages.hpp"

namespace centrec::test {

inline coupling::DemFilmAverages synthetic_dem_film(double drum_diameter, double d = 1.2e-3) {
  coupling::DemFilmAverages a;
  a.drum_radius = 0.5 * drum_diameter;
  a.length = 1.425 * drum_diameter;
  a.omega = 16.76 * std::sqrt(0.12 / drum_diameter);
  a.particle_diameter = d;
  a.particle_density = 3560.0;
  a.mdot = 0.0357 * drum_diameter / 0.12;
  a.sampled_turns = 10;
  for (int i = 0; i < 20; ++i) {
    a.section_z.push_back((i + 0.5) * a.length / 20);
    a.thickness.push_back((4.0 - 0.02 * i) * d);  // thinning toward the outlet
    a.thickness_std.push_back(0.1 * d);
  }
  for (int b = 0; b < 36; ++b) {
    a.bin_theta.push_back((b + 0.5) * 2 * M_PI / 36);
    a.surface_velocity.push_back(0.3);
    a.moving_zone_of_bin.push_back(1);
  }
  for (int k = 0; k < 16; ++k) a.wall_distance_d.push_back(0.25 + 0.5 * k);
  const double levels[3] = {0.3, 0.5, 0.7}, thetas[3] = {M_PI / 4, M_PI / 2, 3 * M_PI / 4};
  for (double z : levels)
    for (double th : thetas) {
      a.arc_theta.push_back(th);
      a.arc_z_over_length.push_back(z);
      std::vector<double> u, s, n;
      for (double c : a.wall_distance_d) {
        u.push_back(c < 1.0 ? 0.0 : 0.1 * (c - 1.0) * (1.0 + 0.2 * z));
        s.push_back(0.01);
        n.push_back(10);
      }
      a.u_mean.push_back(u), a.u_std.push_back(s), a.u_turns.push_back(n);
    }
  a.phi_stationary.assign(16, 0.56);
  a.phi_moving.assign(16, 0.52);
  a.phi_stationary_std.assign(16, 0.01);
  a.phi_moving_std.assign(16, 0.01);
  a.dispersion.assign(16, 1e-7);
  a.dispersion_std.assign(16, 1e-8);
  return a;
}

}  // namespace centrec::test
