#pragma once
// The finite-volume grid on (z, xi = eta / t(z)) built from a film field (docs/thermal_model.md). Cells are the quadrilaterals between axial faces z_i and xi-lines; all
// quantities are per unit circumferential width (planar film, t << drum radius) and
// multiplied by pi * D_drum for receiver totals.
//
// Mass conservation is built in: the mass flux of each stripe through an axial face is
// the exact integral of rho_s phi u over the stripe, rescaled so that every face carries
// the inlet's total; the flux across xi-lines (the wall-normal velocity that a varying
// thickness implies) follows from continuity, so the upwind enthalpy fluxes telescope.
#include <vector>

#include "film_field.hpp"
#include "film_model.hpp"

namespace centrec::thermal {

struct FilmGrid {
  int nz = 0, nxi = 0;
  bool lumped = false;
  double length = 0.0, dz = 0.0, perimeter = 0.0;  // m
  std::vector<double> zc;      // cell centres [nz]
  std::vector<double> tc;      // thickness at centres [nz]
  std::vector<double> tf;      // thickness at axial faces [nz + 1]
  std::vector<double> deta;    // cell height at centres [nz]
  std::vector<double> phi;     // stripe-mean solid fraction [nz * nxi]
  std::vector<double> D;       // wall-normal dispersion at cell centres [nz * nxi]
  std::vector<double> u;       // axial velocity at cell centres (reporting) [nz * nxi]
  std::vector<double> m_axial; // stripe mass flux per width through face i, kg/(m s) [(nz + 1) * nxi]
  std::vector<double> m_xi;    // mass flux per width up through the bottom of cell (i, j) [nz * (nxi + 1)]
  double mass_flux = 0.0;      // per unit width, kg/(m s)
  double max_flux_correction = 0.0;  // largest relative rescaling of a face's mass flux

  int index(int i, int j) const { return i * nxi + j; }
  double eta_center(int i, int j) const { return (j + 0.5) * deta[i]; }
  double volume(int i) const { return dz * deta[i]; }  // per unit width, m2
};

FilmGrid build_film_grid(const FilmField& film, const FilmGridSpec& spec, double rho_s);

}  // namespace centrec::thermal
