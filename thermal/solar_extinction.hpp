#pragma once
// Where the film absorbs the sunlight that enters its surface (docs/thermal_model.md,
// "Surface and solar absorption"): Beer-Lambert extinction below the surface with the
// extinction coefficient of a bed of large opaque spheres,
//     beta(phi) = 1.5 phi / ((1 - phi) d)   (Brewster 2004, J. Heat Transfer 126, 1048),
// the inverse of the mean void chord (2/3) d (1 - phi) / phi. Either from the column's mean
// solid fraction (one depth per column) or from each cell's own phi, so that the optical
// depth tau(eta) = integral from eta to t of beta(phi(eta')) d eta' follows a loose top.
#include <vector>

namespace centrec::thermal {

// Extinction depth in particle diameters at solid fraction phi, 1 / (beta d) = (1 - phi) / (1.5 phi).
double extinction_depth_d_from_phi(double phi);

// Shares of the sunlight absorbed in each cell of one column (cells bottom to top, the last
// at the surface, each deta thick, solid fraction phi[j]) with the local coefficient
// scale^-1 beta(phi[j]): share_j = exp(-tau_above_j) (1 - exp(-dtau_j)), normalised over the
// film so that the shares add up to 1 (what reaches the wall is absorbed in proportion, as
// the column-mean form does). A column with no solid at all absorbs in its top cell.
std::vector<double> local_extinction_shares(const std::vector<double>& phi, double deta, double d, double scale = 1.0);

}  // namespace centrec::thermal
