#pragma once
// DEM averages -> the thermal model's film field (docs/coupling.md).
//
// Tangential averaging: the thermal film is the film averaged over one drum turn.
//  - thickness t(z): the DEM's ring thickness per axial section (already a turn average);
//  - phi(eta): the stationary- and moving-zone profiles weighted by the share of the
//    circumference each zone covers;
//  - u(z, eta): the DEM measures profiles only in the arc sections (moving zone). Their
//    shape is taken as similar around the drum, scaled by the surface velocity: the
//    turn average is the arc mean times (circumference-mean surface velocity) / (mean
//    surface velocity at the arcs). Between the arcs' axial levels u is interpolated
//    linearly in z and held beyond them;
//  - D(eta): the DEM's dispersion is already pooled over the whole drum.
// Bins the DEM left empty (the glued wall layer, above the surface) are filled: u = 0 at
// the wall side, the last value above; phi and D take the nearest sampled bin.
// The mass flux is NOT yet matched here: conserve_mass_flow (film_mass_flow.hpp) does it.
#include <vector>

#include "coupling/dem_film_averages.hpp"
#include "thermal/film_field.hpp"

namespace centrec::coupling {

struct TangentialAverage {
  double moving_fraction = 0.0;   // share of the circumference in the moving zone
  double velocity_factor = 0.0;   // circumference-mean surface velocity / mean at the arcs
  std::vector<double> profile_z;  // axial levels (m) of the arc profiles
  int filled_bins = 0;            // wall-distance bins that took a neighbour's value
  // Per axial level: the DEM profile's own mass flux over all its bins (surface particles
  // above t included), sum of 2 pi rho_s phi u (R - eta) d eta, over the DEM's outlet mdot.
  // Near 1 when the sampled profiles and the measured flow agree (steady, well sampled).
  std::vector<double> profile_flux_over_mdot;
};

struct MappedFilm {
  thermal::FilmField film;  // DEM drum size; drum_diameter = 2 R of the DEM drum
  TangentialAverage tangential;
};

// Throws std::invalid_argument naming the problem (empty film, no moving zone, ...).
MappedFilm map_dem_film(const DemFilmAverages& a);

}  // namespace centrec::coupling
