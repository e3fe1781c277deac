#pragma once
// The analytic film of docs/thermal_model.md: thickness t, solid fraction phi uniform,
// u = 0 within one particle diameter of the wall and linear from there to u_surface at
// eta = t (the paper's suggested profile); an optional wall-normal dispersion D either
// uniform or proportional to the local shear rate, D = c gamma_dot d^2.
#include "film_field.hpp"

namespace centrec::thermal {

struct AnalyticFilm {
  double thickness = 6.0e-3;     // m
  double u_surface = 0.05;       // m/s (axial velocity at the free surface)
  double phi = 0.55;             // solid volume fraction
  double d = 1.2e-3;             // particle diameter, m (also the no-slip layer thickness)
  double D_uniform = 0.0;        // m2/s, added everywhere
  double D_shear_coeff = 0.0;    // c in D = c gamma_dot d^2 in the sheared part
  double drum_diameter = 1.0;    // m
  double length = 1.0;           // m
};

// Throws std::invalid_argument if the parameters are inconsistent (t <= d, ...).
FilmField analytic_film(const AnalyticFilm& a);

// Mass flow (kg/s) carried by the film around the full circumference pi * drum_diameter
// (planar film: t << drum radius).
double film_mass_flow(const FilmField& f, double rho_s, double z);

}  // namespace centrec::thermal
