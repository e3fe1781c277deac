#pragma once
// View factors of the receiver cavity (docs/cavity_model.md): a cylinder of radius R and
// length L whose inner wall is cut into coaxial rings (the film's axial sections), closed
// at z = 0 by the back plate (a disc of radius R) and at z = L by the front plane, which is
// the aperture (a disc of radius r_a <= R) plus, if r_a < R, the front annulus r_a..R.
//
// Every factor follows from one closed form, the factor between two parallel coaxial discs
// (Howell's catalogue of configuration factors, C-41; Siegel & Howell, Thermal Radiation
// Heat Transfer), by view-factor algebra through "virtual" discs of radius R spanning the
// cylinder (e.g. Siegel & Howell's treatment of a ring on the inside of a cylinder):
//   ring [a, b] to ring [c, d] (c >= b):
//       A_i F_ij = pi R^2 [f(c - b) - f(c - a) - f(d - b) + f(d - a)],  f(h) = F(disc R -> disc R, h)
//   ring [a, b] to its own ends: A_i F_i,D(a) = A_i F_i,D(b) = pi R^2 (1 - f(b - a))
//   aperture to the virtual disc at z: g(L - z) = F(disc r_a -> disc R, L - z).
// The exchange areas S_ij = A_i F_ij are built symmetric (reciprocity holds exactly) and
// each row telescopes to A_i (summation to round-off).
#include <vector>

namespace centrec::thermal {

// F from a disc of radius r1 to a parallel coaxial disc of radius r2 at distance h >= 0
// (Howell C-41): with X = 1 + (h^2 + r2^2) / r1^2, F = (X - sqrt(X^2 - 4 r2^2/r1^2)) / 2,
// evaluated without cancellation as 2c / (X + sqrt(X^2 - 4c)), c = r2^2 / r1^2.
// At h = 0 it is min(1, r2^2 / r1^2).
double disc_to_disc_view_factor(double r1, double r2, double h);

// F from a ring element dA on the inside of a cylinder of radius R to the end disc of the
// cylinder at distance h (Siegel & Howell, element on the interior of a cylinder to its
// base): F = ((H^2 + 2) / sqrt(H^2 + 4) - H) / 2, H = h / R. Used by the tests as an
// independent check of the ring factors.
double ring_element_to_end_disc(double R, double h);

// F from a ring element dA on the inside of a cylinder of radius R to a coaxial disc of
// radius r <= R in a plane at axial distance h (Siegel & Howell, element on the interior
// of a cylinder to a coaxial disc):
// with H = h / R, P = r / R, X = 1 + H^2 + P^2: F = (H / 2) (X / sqrt(X^2 - 4 P^2) - 1).
// At r = R it is ring_element_to_end_disc. Differences of two radii give the factor to a
// coaxial annulus (the front plate r_aperture..R); used by the tests as an independent
// check of the front plate's factors.
double ring_element_to_coaxial_disc(double R, double r, double h);

struct CavityViewFactors {
  int n_rings = 0;
  bool front_annulus = false;           // aperture smaller than the drum
  std::vector<double> area;             // m2, per surface
  std::vector<double> S;                // exchange areas A_i F_ij, m2, row-major size x size

  // Surface order: rings 0..n_rings-1 (z = 0 at the back to z = L at the aperture), the
  // back disc, the front annulus (if any), the aperture (last).
  int size() const { return static_cast<int>(area.size()); }
  int back() const { return n_rings; }
  int annulus() const { return front_annulus ? n_rings + 1 : -1; }
  int aperture() const { return size() - 1; }
  double F(int i, int j) const { return S[static_cast<std::size_t>(i) * size() + j] / area[i]; }
  double exchange(int i, int j) const { return S[static_cast<std::size_t>(i) * size() + j]; }
};

// ring_z: ring boundaries 0 = z_0 < z_1 < ... < z_n = L. Throws std::invalid_argument for
// unsorted boundaries, R <= 0 or an aperture radius outside (0, R].
CavityViewFactors cavity_view_factors(double radius, const std::vector<double>& ring_z, double aperture_radius);

}  // namespace centrec::thermal
