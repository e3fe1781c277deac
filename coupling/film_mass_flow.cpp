#include "film_mass_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::coupling {

namespace {
// integral over [0, t_i] of phi u eta^power, the data linear between eta points (and held
// beyond the last): the integrand is a cubic per piece, so 3-point Gauss is exact.
double film_integral(const thermal::FilmField& f, std::size_t i, int power) {
  static const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const std::size_t n = f.neta(), o = i * n;
  const double t = f.t[i];
  double sum = 0.0;
  for (std::size_t j = 0; j + 1 < n && f.eta[j] < t; ++j) {
    const double a = f.eta[j], b = std::min(f.eta[j + 1], t), h = f.eta[j + 1] - f.eta[j];
    for (int q = 0; q < 3; ++q) {
      const double e = 0.5 * (a + b) + 0.5 * (b - a) * x[q], s = (e - a) / h;
      const double phi = (1 - s) * f.phi[o + j] + s * f.phi[o + j + 1];
      const double u = (1 - s) * f.u[o + j] + s * f.u[o + j + 1];
      sum += 0.5 * (b - a) * w[q] * phi * u * (power ? e : 1.0);
    }
  }
  return sum;
}
}  // namespace

double phi_u_integral(const thermal::FilmField& f, std::size_t i) { return film_integral(f, i, 0); }
double phi_u_eta_integral(const thermal::FilmField& f, std::size_t i) { return film_integral(f, i, 1); }

double cylindrical_mass_flow(const thermal::FilmField& f, std::size_t i, double rho_s, double drum_radius) {
  return 2.0 * M_PI * rho_s * (drum_radius * phi_u_integral(f, i) - phi_u_eta_integral(f, i));
}

double planar_mass_flow(const thermal::FilmField& f, std::size_t i, double rho_s) {
  return M_PI * f.drum_diameter * rho_s * phi_u_integral(f, i);
}

MassFlowConservation conserve_mass_flow(thermal::FilmField& f, double rho_s, double mdot) {
  if (!(mdot > 0.0)) throw std::invalid_argument("conserve_mass_flow: mdot must be > 0");
  MassFlowConservation c;
  c.drum_radius = 0.5 * f.drum_diameter;
  c.mdot = mdot;
  double p_sum = 0.0, q_sum = 0.0;
  for (std::size_t i = 0; i < f.nz(); ++i) {
    const double p = phi_u_integral(f, i);
    if (!(p > 0.0))
      throw std::invalid_argument("conserve_mass_flow: section " + std::to_string(i) + " (z = " +
                                  std::to_string(f.z[i]) + " m) carries no mass flux");
    p_sum += p;
    q_sum += phi_u_eta_integral(f, i);
    c.sampled_over_mdot.push_back(cylindrical_mass_flow(f, i, rho_s, c.drum_radius) / mdot);
  }
  c.mean_flux_depth = q_sum / p_sum;
  // Every section carries mdot by the cylindrical formula; the planar film's perimeter is
  // taken at the inlet section's flux-weighted radius, where the thermal model reads its
  // total (its grid rescales the other faces to it: mass_flux_max_correction).
  const double inlet_depth = phi_u_eta_integral(f, 0) / phi_u_integral(f, 0);
  c.planar_diameter = 2.0 * (c.drum_radius - inlet_depth);
  const std::size_t n = f.neta();
  for (std::size_t i = 0; i < f.nz(); ++i) {
    const double scale = mdot / cylindrical_mass_flow(f, i, rho_s, c.drum_radius);
    for (std::size_t j = 0; j < n; ++j) {
      f.u[i * n + j] *= scale;
      if (!f.u_std.empty()) f.u_std[i * n + j] *= scale;
    }
    c.max_cylindrical_error =
        std::max(c.max_cylindrical_error, std::abs(cylindrical_mass_flow(f, i, rho_s, c.drum_radius) / mdot - 1.0));
  }
  f.drum_diameter = c.planar_diameter;
  f.mdot = mdot;
  return c;
}

}  // namespace centrec::coupling
