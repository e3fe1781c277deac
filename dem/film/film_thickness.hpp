#pragma once
// Film thickness of one film section by the paper's eqs (4)-(7).
//
//   (4) A_surf = arc_fraction * l_sec * pi * (D - 2 t)
//   (5) n_p    = A_surf * d * (1 - f_s) / V_p,     V_p = pi d^3 / 6
//   (6) r_p    = sort(sqrt(x^2 + y^2), ascending)
//   (7) t      = D/2 - mean(r_p[0 .. n_p-1]) + d/2
//
// iterated from t = 0 until n_p stops changing (t is then fixed too). arc_fraction is 1
// for a full ring and the bin's share of 2 pi for a tangential bin (eq 4 on the arc).
// f_s enters as the paper writes it, (1 - f_s); at the paper's f_s = 0.5 this equals f_s,
// so the n_p surface particles fill a layer one diameter deep at solid fraction 0.5.
//
// Polydisperse particles: d is the mean diameter of the particles (the caller passes it;
// FilmSectionSampler uses the snapshot's mean 2 * radius), V_p = pi d^3 / 6 of that mean.
#include <cstddef>

namespace centrec::film {

struct FilmThicknessParams {
  double cavity_diameter = 0.0;    // D, m
  double section_length = 0.0;     // l_sec, m
  double particle_diameter = 0.0;  // d, m (mean diameter if polydisperse)
  double solid_fraction = 0.5;     // f_s of eq (5)
  double arc_fraction = 1.0;       // (0, 1]: share of the full ring
  int max_iterations = 100;
};

struct FilmThicknessResult {
  double thickness = 0.0;       // t_film, m
  std::size_t n_surface = 0;    // n_p used in the last evaluation of eq (7)
  int iterations = 0;
  bool converged = false;       // n_p repeated within max_iterations
  bool underfilled = false;     // eq (5) asked for more particles than the section holds; all used
};

// r_sorted: radial positions (m) of the particles whose centres lie in the section,
// sorted ascending (eq 6). n may be 0 (thickness 0, underfilled).
FilmThicknessResult film_thickness_sorted(const double* r_sorted, std::size_t n, const FilmThicknessParams& p);

// As above for unsorted radial positions (copies and sorts them).
FilmThicknessResult film_thickness(const double* r, std::size_t n, const FilmThicknessParams& p);

// n_p of eq (5) for a trial thickness t, rounded to the nearest integer (at least 1).
std::size_t surface_particle_count(double t, const FilmThicknessParams& p);

}  // namespace centrec::film
