#pragma once
// DEM averages -> the thermal model's film field: the film as the DEM measured it
// (docs/coupling.md "Film as measured").
//
// Per axial section the full-circumference profiles (dem/film/ring_profile.hpp) give the
// solid fraction phi(eta) (free particles, plus the glued wall layer added back) and the
// axial volume flux density phi*u(eta); the film's velocity is u = (phi*u) / phi, the
// mass-weighted mean over the whole circumference, stationary and moving zones together.
// The thermal film reaches from the wall to the top of the last bin, counted from the wall
// without a gap, whose solid fraction is at least `phi_cut`: the flowing layer, not the
// eqs 4-7 thickness (reported beside it). A drum contributes its developed sections (z/L
// 0.2-0.8), held toward the ends; a slice its one section. Nothing is rescaled: the flow the film
// carries is checked against the DEM's measured flow by film_mass_flow.hpp.
#include <vector>

#include "coupling/dem_film_averages.hpp"
#include "coupling/film_mappings.hpp"
#include "dem/film/developed_film.hpp"
#include "thermal/film_field.hpp"

namespace centrec::coupling {

// The solid fraction below which the DEM's top bins are the loose particles above the
// film, not film (docs/coupling.md "Film as measured": what the cut leaves out is reported).
constexpr double kFilmSolidFractionCut = 0.1;
// Wall-distance points per gap between bin centres (kPointsPerGap - 1 between them): phi and
// the flux phi u linear in between, so the film's flow is its bins' to 0.5-0.7 % (1: phi and
// u each linear, 3-10 % more).
constexpr int kPointsPerGap = 4;
// A drum's developed film: the axial sections used, as fractions of its length (the same
// window as the DEM's solid-fraction and dispersion samplers).
using film::kDevelopedFrom;
using film::kDevelopedTo;

struct FilmCut {
  double phi_cut = 0.0;
  std::vector<double> thickness;          // m, per section: where the film ends
  std::vector<double> flow_within_share;  // per section: the film's bin flow / all bins' flow
};

struct MappedFilm {
  thermal::FilmField film;  // DEM drum size; drum_diameter = 2 R of the DEM drum
  FilmCut cut;
};

// Where a section's film ends: at the top of its last bin with phi >= phi_cut (whole bins),
// or where the profile, linear between bin centres, crosses phi_cut (continuous in the
// profile: a film does not jump by a bin when its top bin's phi passes the cut), or where the
// flow counted from the wall (uniform within a bin) reaches kCarriedFlowShare of the
// section's flow: the sparse, fast particles over a fed drum's film carry 15-65 % of its
// flow above phi 0.1 (docs/coupling.md "Film along the drum").
enum class FilmTop { whole_bins, at_crossing, carried_flow };
// The share of a section's measured flow inside a film whose top is set by the carried flow.
constexpr double kCarriedFlowShare = 0.995;

// The developed sections (a slice: its one section), whole bins. Throws
// std::invalid_argument naming the problem (empty film, no flow, ...).
MappedFilm map_dem_film(const DemFilmAverages& a, double phi_cut = kFilmSolidFractionCut,
                        FilmTop top_at = FilmTop::whole_bins);
// The given sections (indices into a.ring_z, increasing), cut as top_at says (phi_cut unused
// for carried_flow).
MappedFilm map_dem_sections(const DemFilmAverages& a, const std::vector<std::size_t>& sections, double phi_cut,
                            FilmTop top_at);

// map_dem_film at kFilmSolidFractionCut as a row of film_mappings(): the cut as the figure
// film_solid_fraction_cut, per section the film's thickness (film_thickness, m) and the
// share of the bins' flow inside it (flow_within_film_share).
FilmMappingResult map_film_as_measured(const DemFilmAverages& a);
// The same sections with the film's top where it carries kCarriedFlowShare of the flow
// (FilmTop::carried_flow): the loose top inside it.
FilmMappingResult map_film_as_measured_carried_flow(const DemFilmAverages& a);

}  // namespace centrec::coupling
