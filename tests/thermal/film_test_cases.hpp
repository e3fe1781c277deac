#pragma once
// Shared set-ups of the thermal regression tests: a CentRec-like operating point and
// simple films with known solutions. Header-only, test code only.
#include <chrono>

#include "thermal/analytic_film.hpp"
#include "thermal/film_field.hpp"
#include "thermal/film_model.hpp"

namespace centrec::thermal::testcases {

// A CentRec-like operating point: 1 m drum, 1 m long, 6 mm film of 1.2 mm bauxite,
// u_surface 0.26 m/s (mdot ~ 3.9 kg/s), 1 MW/m2 uniform, open surface, U_w = 1 W/(m2 K).
inline AnalyticFilm centrec_film() {
  AnalyticFilm a;
  a.thickness = 6e-3;
  a.u_surface = 0.26;
  a.phi = 0.55;
  a.d = 1.2e-3;
  a.D_shear_coeff = 0.05;
  a.drum_diameter = 1.0;
  a.length = 1.0;
  return a;
}

inline FilmModel centrec_model() {
  FilmModel m;
  m.flux.kind = FluxProfile::Kind::uniform;
  m.flux.q = 1.0e6;
  m.surface.h_conv = 10.0;
  m.wall.U_w = 1.0;
  m.T_in = 873.15;
  return m;
}

// The CentRec model inside a cavity of aperture 0.7 m under 300 kW/m2 on the film, sunlight
// absorbed with the Beer-Lambert depth from the solid fraction.
inline FilmModel cavity_model_q300k() {
  FilmModel m = centrec_model();
  m.flux.q = 3.0e5;
  m.cavity.enabled = true;
  m.cavity.aperture_diameter = 0.7;
  m.surface.extinction_depth_d = -1.0;
  return m;
}

// Plug flow: u uniform over the whole depth (no resting layer), uniform phi, no dispersion.
inline FilmField plug_film(double thickness, double u, double phi, double drum_diameter, double length) {
  FilmField f;
  f.z = {0.0, length};
  f.eta = {0.0, thickness};
  f.t = {thickness, thickness};
  f.u = {u, u, u, u};
  f.phi = {phi, phi, phi, phi};
  f.D = {0.0, 0.0, 0.0, 0.0};
  f.drum_diameter = drum_diameter;
  f.length = length;
  f.particle_diameter = 1.2e-3;
  return f;
}

// A 6 mm plug film at 0.05 m/s, 1 m drum and length, whose solid fraction is 0.55 up to 3.6 mm
// and falls linearly to 0.10 at the surface (a loose top like the DEM film's), no dispersion.
inline FilmField loose_top_film() {
  FilmField f = plug_film(6e-3, 0.05, 0.55, 1.0, 1.0);
  f.eta = {0.0, 3.6e-3, 6e-3};
  f.u = {0.05, 0.05, 0.05, 0.05, 0.05, 0.05};
  f.phi = {0.55, 0.55, 0.10, 0.55, 0.55, 0.10};
  f.D = {0, 0, 0, 0, 0, 0};
  return f;
}

// No losses anywhere: no emission (F = 0), no convection, adiabatic wall.
inline void remove_losses(FilmModel& m) {
  m.surface.loss_factor = 0.0;
  m.surface.h_conv = 0.0;
  m.wall.adiabatic = true;
}

// The transient tests' grid: 60 sections x 16 cells across the film.
inline FilmGridSpec small_grid() {
  FilmGridSpec spec;
  spec.nz = 60;
  spec.nxi = 16;
  return spec;
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace centrec::thermal::testcases
