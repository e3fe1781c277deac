#pragma once
// Mass flux of a film field and its conservation (docs/coupling.md):
//   mdot = 2 pi rho_s integral_0^t phi u (R - eta) d eta     (the cylindrical film)
// The thermal model is planar per unit width with perimeter pi * drum_diameter
// (thermal/film_grid.hpp), i.e. it would carry pi D rho_s integral(phi u). The two agree
// when the planar film sits at the flux-weighted mean radius R - eta_bar.
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

// The flow the mapped film carries against the DEM's measured flow, at the DEM's scale:
// a check, nothing is changed (docs/coupling.md "Flux closure"). A coupled run refuses a
// film whose mean closure misses by more than kFlowClosureTolerance.
constexpr double kFlowClosureTolerance = 0.05;
struct FlowClosure {
  double measured_mdot = 0.0;              // kg/s, the DEM's (outlet of a drum, axial flow of a slice)
  std::vector<double> section_over_measured;  // per section: cylindrical flow of the film / measured
  double mean_over_measured = 0.0;         // their mean
  double worst_error = 0.0;                // max |section / measured - 1|
  double min_over_measured = 0.0, max_over_measured = 0.0;  // the lowest and highest section
};
FlowClosure flow_closure(const thermal::FilmField& f, double rho_s, double measured_mdot);

// Imposes `mdot` on the film with ONE factor for all of it (u and u_std scaled alike), the
// factor = mdot / the inlet section's cylindrical flow (where the thermal model reads its
// total; the other sections' spread is flow_closure's); the planar film's
// perimeter is taken at the inlet section's flux-weighted radius R - eta_bar, where the
// thermal model reads its total. f's drum_diameter must be the true drum's on entry.
struct ImposedFlow {
  double drum_radius = 0.0;      // m, the true drum's
  double mdot = 0.0;             // kg/s imposed
  double film_mdot = 0.0;        // kg/s, the inlet section's cylindrical flow before
  double factor = 0.0;           // the one velocity factor applied: mdot / film_mdot
  double mean_flux_depth = 0.0;  // eta_bar of the inlet section, m
  double planar_diameter = 0.0;  // 2 (R - eta_bar), m: the film's drum_diameter afterwards
};
ImposedFlow impose_mass_flow(thermal::FilmField& f, double rho_s, double mdot);

}  // namespace centrec::coupling
