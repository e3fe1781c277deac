#include "film_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stripe_integral.hpp"

namespace centrec::thermal {

FilmGrid build_film_grid(const FilmField& film, const FilmGridSpec& spec, double rho_s) {
  film.check();
  if (spec.nz < 2) throw std::invalid_argument("grid: nz must be >= 2, got " + std::to_string(spec.nz));
  if (!spec.lumped && spec.nxi < 2)
    throw std::invalid_argument("grid: nxi must be >= 2 for the 2D model, got " + std::to_string(spec.nxi));
  if (!(film.length > 0.0) || !(film.drum_diameter > 0.0))
    throw std::invalid_argument("film field: length and drum diameter must be > 0");
  FilmGrid g;
  g.nz = spec.nz;
  g.nxi = spec.lumped ? 1 : spec.nxi;
  g.lumped = spec.lumped;
  g.length = film.length;
  g.dz = film.length / g.nz;
  g.perimeter = M_PI * film.drum_diameter;
  const int nz = g.nz, nxi = g.nxi;
  g.zc.resize(nz);
  g.tc.resize(nz);
  g.deta.resize(nz);
  g.tf.resize(nz + 1);
  for (int i = 0; i <= nz; ++i) g.tf[i] = film.thickness(i * g.dz);
  g.phi.resize(nz * nxi);
  g.D.resize(nz * nxi);
  g.u.resize(nz * nxi);
  for (int i = 0; i < nz; ++i) {
    g.zc[i] = (i + 0.5) * g.dz;
    g.tc[i] = film.thickness(g.zc[i]);
    g.deta[i] = g.tc[i] / nxi;
    for (int j = 0; j < nxi; ++j) {
      const double a = j * g.deta[i], b = (j + 1) * g.deta[i], e = g.eta_center(i, j);
      g.phi[g.index(i, j)] = stripe_integral_phi(film, g.zc[i], a, b) / g.deta[i];
      g.D[g.index(i, j)] = film.sample(film.D, g.zc[i], e);
      g.u[g.index(i, j)] = film.sample(film.u, g.zc[i], e);
    }
  }
  // Stripe mass fluxes through the axial faces, each face rescaled to the inlet total.
  g.m_axial.assign((nz + 1) * nxi, 0.0);
  for (int i = 0; i <= nz; ++i) {
    const double z = i * g.dz, h = g.tf[i] / nxi;
    double total = 0.0;
    for (int j = 0; j < nxi; ++j) {
      const double m = rho_s * stripe_integral_phi_u(film, z, j * h, (j + 1) * h);
      g.m_axial[i * nxi + j] = m;
      total += m;
    }
    if (i == 0) g.mass_flux = total;
    // A resting film (no flow at all) is allowed (pure conduction); a film that flows at one
    // section and rests at another is not.
    if ((g.mass_flux > 0.0) != (total > 0.0))
      throw std::invalid_argument("film field: mass flux is zero at some sections only (z = " + std::to_string(z) +
                                  " m)");
    if (!(total > 0.0)) continue;
    const double scale = g.mass_flux / total;
    g.max_flux_correction = std::max(g.max_flux_correction, std::abs(scale - 1.0));
    for (int j = 0; j < nxi; ++j) g.m_axial[i * nxi + j] *= scale;
  }
  // Continuity per cell: what enters through the west face and leaves through the east face
  // of the stripes below a xi-line crosses that line.
  g.m_xi.assign(nz * (nxi + 1), 0.0);
  for (int i = 0; i < nz; ++i) {
    double up = 0.0;
    for (int j = 0; j < nxi; ++j) {
      up += g.m_axial[i * nxi + j] - g.m_axial[(i + 1) * nxi + j];
      g.m_xi[i * (nxi + 1) + j + 1] = up;
    }
    g.m_xi[i * (nxi + 1) + nxi] = 0.0;  // nothing leaves through the free surface (round-off)
  }
  return g;
}

}  // namespace centrec::thermal
