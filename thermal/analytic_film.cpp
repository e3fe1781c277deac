#include "analytic_film.hpp"

#include <cmath>
#include <stdexcept>

#include "stripe_integral.hpp"

namespace centrec::thermal {

FilmField analytic_film(const AnalyticFilm& a) {
  if (!(a.thickness > a.d))
    throw std::invalid_argument("analytic film: thickness (" + std::to_string(a.thickness) +
                                " m) must exceed one particle diameter (" + std::to_string(a.d) + " m)");
  FilmField f;
  f.z = {0.0, a.length};
  // Break points of the piecewise-linear profile: wall, top of the resting layer, surface.
  f.eta = {0.0, a.d, a.thickness};
  f.t = {a.thickness, a.thickness};
  const double gamma_dot = a.u_surface / (a.thickness - a.d);
  const double D_sheared = a.D_uniform + a.D_shear_coeff * gamma_dot * a.d * a.d;
  for (int i = 0; i < 2; ++i) {
    f.u.insert(f.u.end(), {0.0, 0.0, a.u_surface});
    f.phi.insert(f.phi.end(), {a.phi, a.phi, a.phi});
    // The resting layer is not sheared; dispersion ramps in linearly over it.
    f.D.insert(f.D.end(), {a.D_uniform, D_sheared, D_sheared});
  }
  f.drum_diameter = a.drum_diameter;
  f.length = a.length;
  f.particle_diameter = a.d;
  f.scaling = "analytic film (no scaling)";
  f.check();
  return f;
}

double film_mass_flow(const FilmField& f, double rho_s, double z) {
  const double m_per_width = rho_s * stripe_integral_phi_u(f, z, 0.0, f.thickness(z));
  return M_PI * f.drum_diameter * m_per_width;
}

}  // namespace centrec::thermal
