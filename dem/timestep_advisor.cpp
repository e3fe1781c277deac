#include "timestep_advisor.hpp"

#include <cmath>
#include <cstdio>

namespace centrec::dem {

double rayleigh_time(const Material& m, double radius) {
  const double shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  return M_PI * radius * std::sqrt(m.density / shear_modulus) / (0.1631 * m.poisson_ratio + 0.8766);
}

double hertz_contact_time(double m_eff, double r_eff, double E_eff, double v) {
  return 2.868 * std::pow(m_eff * m_eff / (r_eff * E_eff * E_eff * v), 0.2);
}

double hertz_max_overlap(double m_eff, double r_eff, double E_eff, double v) {
  return std::pow(15.0 * m_eff * v * v / (16.0 * E_eff * std::sqrt(r_eff)), 0.4);
}

std::string TimeStepAdvice::report() const {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "time step: Rayleigh time %.4g s, Hertz contact time %.4g s at %.3g m/s; "
                "recommended dt %.4g s; stability bound %.4g s (min of %.1f x Rayleigh, %.1f x Hertz)",
                rayleigh_time, hertz_time, max_impact_speed, recommended, stable_bound, kRayleighBound, kHertzBound);
  return buf;
}

}  // namespace centrec::dem
