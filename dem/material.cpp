#include "material.hpp"

namespace centrec::dem {

PairConstants make_pair_constants(const Material& a, const Material& b, const PairInteraction& p) {
  PairConstants c;
  c.E_eff = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                   (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  c.G_eff = 1.0 / (2.0 * (2.0 - a.poisson_ratio) * (1.0 + a.poisson_ratio) / a.youngs_modulus +
                   2.0 * (2.0 - b.poisson_ratio) * (1.0 + b.poisson_ratio) / b.youngs_modulus);
  const double le = std::log(p.restitution);
  c.beta = p.restitution >= 1.0 ? 0.0 : le / std::sqrt(le * le + M_PI * M_PI);
  c.mu = p.friction;
  c.mu_r = p.rolling_friction;
  c.rolling = p.rolling_model;
  c.rolling_coefficients = p.rolling_coefficients;
  const double damp = -2.0 * std::sqrt(5.0 / 6.0) * c.beta;
  c.damp_n = damp * std::sqrt(2.0 * c.E_eff);
  c.damp_t = damp * std::sqrt(8.0 * c.G_eff);
  return c;
}

}  // namespace centrec::dem
