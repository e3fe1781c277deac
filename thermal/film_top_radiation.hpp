#pragma once
// The thermal band in the film's loose top as a participating medium (docs/thermal_model.md,
// "The film top as a participating medium"): a two-flux (Schuster-Schwarzschild) model of a
// bed of large grey, diffusely reflecting opaque spheres over the top cells of a column, and
// the conduction of the dilute top.
//
// Per unit volume the bed extinguishes with beta = 1.5 phi / ((1 - phi) d), the inverse of
// the mean void chord (Brewster 2004, J. Heat Transfer 126, 1048; thermal/solar_extinction.hpp),
// absorbs kappa = eps beta and scatters sigma_s = (1 - eps) beta (geometric optics: each hit
// absorbs eps, reflects 1 - eps diffusely). With hemispherically isotropic intensities the
// upward and downward fluxes q+ and q- obey the two-flux (Schuster-Schwarzschild) equations
// (Modest, Radiative Heat Transfer, the two-flux approximation; diffusivity factor 2)
//     dq+/deta = -2 (kappa + b sigma_s) q+ + 2 b sigma_s q- + 2 kappa sigma T^4
//    -dq-/deta = -2 (kappa + b sigma_s) q- + 2 b sigma_s q+ + 2 kappa sigma T^4
// with b the share scattered into the opposite hemisphere (diffuse-sphere phase function).
// Each cell is a homogeneous isothermal layer with the exact two-flux reflectance R and
// transmittance T; it emits (1 - R - T) sigma T^4 from each face (Kirchhoff). The cell's net
// absorption is the difference of its face fluxes, so the column's cells, the boundary
// below and the flux leaving the top add up to zero (the energy balance telescopes).
#include <vector>

namespace centrec::thermal {

// Share of the radiation a large diffusely reflecting sphere scatters into the hemisphere
// opposite to a hemispherically isotropic incident field: the diffuse-sphere phase function
// p(Theta) = 8 / (3 pi) (sin Theta - Theta cos Theta) (Modest, Radiative Heat Transfer, large
// diffusely reflecting spheres) integrated over the two
// hemispheres by quadrature. 0.5 would be isotropic scattering.
double diffuse_sphere_backscatter_fraction();

// Diffuse reflectance and transmittance of a homogeneous two-flux layer.
struct TwoFluxLayer {
  double R = 0.0, T = 1.0;
};
// A layer of thickness L (m) at solid fraction phi of spheres of diameter d and emissivity eps,
// back-scatter share b.
TwoFluxLayer two_flux_layer(double phi, double L, double d, double eps, double b);

// Linear response of one column's radiative zone: its n cells (bottom to top, each deta
// thick), an opaque black boundary below at emissive power E_below, the irradiation H from
// above. Sources s = (E_0 .. E_{n-1}, E_below, H), E_k = sigma T_k^4 (W/m2). Per unit area:
//   absorbed in zone cell j      = sum_k absorbed[j (n + 2) + k] s_k
//   absorbed by the boundary     = sum_k below[k] s_k
//   leaving the top (q+ at top)  = sum_k leaving[k] s_k
// so that the film's net emission is leaving . s - H, and its diffuse emissivity towards the
// cavity 1 - leaving[n + 1].
struct TwoFluxColumn {
  int n = 0;
  std::vector<double> absorbed, below, leaving;
  double emissivity() const { return 1.0 - leaving[n + 1]; }
};
TwoFluxColumn two_flux_column(const std::vector<double>& phi, double deta, double d, double eps, double b);

// Conduction of a dispersion of spheres (conductivity k_s) in a continuous gas (k_g) at solid
// fraction phi: Maxwell's (Maxwell-Eucken) formula, the Hashin-Shtrikman lower bound,
//   k / k_g = (2 + kappa + 2 phi (kappa - 1)) / (2 + kappa - phi (kappa - 1)),  kappa = k_s / k_g
// (Maxwell 1873, A Treatise on Electricity and Magnetism, art. 314; Hashin & Shtrikman 1962,
// J. Appl. Phys. 33, 3125). Exact to first order in phi for spheres without contacts: the
// loose top's particles are not in lasting contact, and their collisional transport is the
// film's mixing term.
double maxwell_dispersion_conductivity(double k_s, double k_g, double phi);

}  // namespace centrec::thermal
