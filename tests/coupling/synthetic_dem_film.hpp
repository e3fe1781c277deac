#pragma once
// A synthetic DEM film (what dem.h5 /film holds) with known answers: in every axial
// section a dense film to 4.5 d (solid fraction 0.55) under a loose top (0.05 to 6 d, empty
// above), the paper's velocity profile (u = 0 below 1 d, linear above), and the measured
// flow equal to what the bins carry.
#include <cmath>

#include "coupling/dem_film_averages.hpp"

namespace centrec::test {

inline double synthetic_phi(double c_d) { return c_d < 4.5 ? 0.55 : c_d < 6.0 ? 0.05 : 0.0; }
inline double synthetic_u(double c_d) { return c_d < 1.0 ? 0.0 : 0.1 * (c_d - 1.0); }

inline coupling::DemFilmAverages synthetic_dem_film(double drum_diameter, double d = 1.2e-3, int sections = 20) {
  coupling::DemFilmAverages a;
  a.drum_radius = 0.5 * drum_diameter;
  a.length = 1.425 * drum_diameter;
  a.omega = 16.76 * std::sqrt(0.12 / drum_diameter);
  a.particle_diameter = d;
  a.particle_density = 3560.0;
  a.sampled_turns = 10;
  a.steady = true;
  a.moving_fraction = 0.5;
  for (int k = 0; k < 16; ++k) a.wall_distance_d.push_back(0.25 + 0.5 * k);
  const double w = 0.5 * d;
  double flow0 = 0.0;
  for (int i = 0; i < sections; ++i) {
    const double zl = (i + 0.5) / sections;
    a.section_z.push_back(zl * a.length);
    a.ring_z.push_back(zl * a.length);
    a.thickness.push_back(4.6 * d);  // eqs 4-7 would read about this
    a.thickness_std.push_back(0.1 * d);
    std::vector<double> phi, flux;
    for (double c : a.wall_distance_d) {
      phi.push_back(synthetic_phi(c));
      flux.push_back(synthetic_phi(c) * synthetic_u(c));
      if (i == 0) {  // exact shell areas: the section's axial flow carried by the bins
        const double ro = a.drum_radius - (c - 0.25) * d, ri = ro - w;
        flow0 += a.particle_density * flux.back() * M_PI * (ro * ro - ri * ri);
      }
    }
    a.ring_phi.push_back(phi);
    a.ring_flux.push_back(flux);
    a.ring_phi_std.push_back(std::vector<double>(16, 0.01));
    a.ring_flux_std.push_back(std::vector<double>(16, 0.001));
  }
  a.mdot = a.mdot_target = flow0;
  a.dispersion.assign(16, 1e-7);
  a.dispersion_std.assign(16, 1e-8);
  return a;
}

}  // namespace centrec::test
