#pragma once
// Mass flux of a film field and its conservation (docs/coupling.md):
//   mdot = 2 pi rho_s integral_0^t phi u (R - eta) d eta     (the cylindrical film)
// The thermal model is planar per unit width with perimeter pi * drum_diameter
// (thermal/film_grid.hpp), i.e. it would carry pi D rho_s integral(phi u). The two agree
// when the planar film sits at the flux-weighted mean radius R - eta_bar, so
// conserve_mass_flow scales u per section so that each carries the DEM's mdot by the
// cylindrical formula, and sets the film's drum_diameter to 2 (R - eta_bar) of the inlet
// section, where the thermal model reads its total: both totals are then mdot.
#include <vector>

#include "thermal/film_field.hpp"

namespace centrec::coupling {

// Integrals over the film of section i (0..t_i) of the piecewise-linear data, exact
// (3-point Gauss per piece): integral phi u d eta (m2/s) and integral phi u eta d eta (m3/s).
double phi_u_integral(const thermal::FilmField& f, std::size_t i);
double phi_u_eta_integral(const thermal::FilmField& f, std::size_t i);

// 2 pi rho_s integral phi u (R - eta) d eta of section i, kg/s.
double cylindrical_mass_flow(const thermal::FilmField& f, std::size_t i, double rho_s, double drum_radius);
// pi * f.drum_diameter * rho_s * integral phi u d eta: what the thermal model carries, kg/s.
double planar_mass_flow(const thermal::FilmField& f, std::size_t i, double rho_s);

struct MassFlowConservation {
  double drum_radius = 0.0;         // m, the true drum's
  double mdot = 0.0;                // kg/s imposed
  double mean_flux_depth = 0.0;     // eta_bar: flux-weighted mean wall distance over the film, m
  double planar_diameter = 0.0;     // 2 (R - eta_bar of the inlet section), m: the film's drum_diameter afterwards
  std::vector<double> sampled_over_mdot;  // per section: the film's cylindrical flux before scaling / mdot
  double max_cylindrical_error = 0.0;     // after scaling: max |cylindrical flux / mdot - 1|
};

// Scales u (and u_std) of every section so it carries `mdot` (see above); f's
// drum_diameter must be the true drum's on entry. Throws std::invalid_argument if a
// section carries no flux.
MassFlowConservation conserve_mass_flow(thermal::FilmField& f, double rho_s, double mdot);

}  // namespace centrec::coupling
