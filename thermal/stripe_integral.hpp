#pragma once
// Exact integrals over a wall-distance interval of the piecewise-linear film field data:
// the mass flux per unit width of one grid stripe needs integral(phi u d eta), which must be
// exact so that the discrete mass flow equals the film's (conservation, docs/thermal_model.md).
#include "film_field.hpp"

namespace centrec::thermal {

// integral_a^b phi(z, eta) u(z, eta) d eta  (m2/s), exact for the bilinear interpolant
// (piecewise quadratic in eta between the eta points: Simpson per piece).
double stripe_integral_phi_u(const FilmField& f, double z, double a, double b);
// integral_a^b phi(z, eta) d eta  (m)
double stripe_integral_phi(const FilmField& f, double z, double a, double b);

}  // namespace centrec::thermal
