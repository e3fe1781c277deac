#include "solar_extinction.hpp"

#include <cmath>

namespace centrec::thermal {

double extinction_depth_d_from_phi(double phi) { return (1.0 - phi) / (1.5 * phi); }

std::vector<double> local_extinction_shares(const std::vector<double>& phi, double deta, double d, double scale) {
  const std::size_t n = phi.size();
  std::vector<double> share(n, 0.0);
  if (n == 0) return share;
  double tau = 0.0;  // optical depth above the current cell
  for (std::size_t k = n; k-- > 0;) {
    const double dtau = phi[k] > 0.0 ? deta / (scale * extinction_depth_d_from_phi(phi[k]) * d) : 0.0;
    share[k] = std::exp(-tau) * -std::expm1(-dtau);
    tau += dtau;
  }
  const double absorbed = -std::expm1(-tau);
  if (!(absorbed > 1e-300)) {
    share.assign(n, 0.0);
    share[n - 1] = 1.0;
    return share;
  }
  for (double& s : share) s /= absorbed;
  return share;
}

}  // namespace centrec::thermal
