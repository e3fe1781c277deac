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

FlowClosure flow_closure(const thermal::FilmField& f, double rho_s, double measured_mdot) {
  if (!(measured_mdot > 0.0)) throw std::invalid_argument("flow closure: the measured mass flow must be > 0");
  FlowClosure c;
  c.measured_mdot = measured_mdot;
  const double R = 0.5 * f.drum_diameter;
  double sum = 0.0;
  c.min_over_measured = 1e300, c.max_over_measured = -1e300;
  for (std::size_t i = 0; i < f.nz(); ++i) {
    const double r = cylindrical_mass_flow(f, i, rho_s, R) / measured_mdot;
    c.section_over_measured.push_back(r);
    c.worst_error = std::max(c.worst_error, std::abs(r - 1.0));
    c.min_over_measured = std::min(c.min_over_measured, r), c.max_over_measured = std::max(c.max_over_measured, r);
    sum += r;
  }
  c.mean_over_measured = sum / static_cast<double>(f.nz());
  return c;
}

ImposedFlow impose_mass_flow(thermal::FilmField& f, double rho_s, double mdot) {
  if (!(mdot > 0.0)) throw std::invalid_argument("impose_mass_flow: mdot must be > 0");
  ImposedFlow c;
  c.drum_radius = 0.5 * f.drum_diameter;
  c.mdot = mdot;
  for (std::size_t i = 0; i < f.nz(); ++i)
    if (!(cylindrical_mass_flow(f, i, rho_s, c.drum_radius) > 0.0))
      throw std::invalid_argument("impose_mass_flow: section " + std::to_string(i) + " (z = " +
                                  std::to_string(f.z[i]) + " m) carries no mass flux");
  // The thermal model reads its total at the inlet section (its grid carries that total
  // through every face, thermal/film_grid.hpp), so the one factor is set there; how far the
  // other sections differ is the closure's spread (flow_closure).
  c.film_mdot = cylindrical_mass_flow(f, 0, rho_s, c.drum_radius);
  c.factor = mdot / c.film_mdot;
  c.mean_flux_depth = phi_u_eta_integral(f, 0) / phi_u_integral(f, 0);
  c.planar_diameter = 2.0 * (c.drum_radius - c.mean_flux_depth);
  for (double& u : f.u) u *= c.factor;
  for (double& u : f.u_std) u *= c.factor;
  f.drum_diameter = c.planar_diameter;
  f.mdot = mdot;
  return c;
}

}  // namespace centrec::coupling
