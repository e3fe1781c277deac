#pragma once
// DEM averages of a fed drum -> a thermal film that follows the drum along z (docs/coupling.md
// "Film along the drum"): every axial section downstream of the feeder region, each with its
// own full-circumference profiles (the fast stream of freshly fed particles over the standing
// base upstream, the developed film further on, the film speeding up to the outlet), cut
// where the profile crosses the solid-fraction cut (FilmTop::at_crossing). The thermal film
// holds the first section's film upstream of it. Nothing is rescaled: the flux closure
// (film_mass_flow.hpp) is checked section by section against the drum's outlet flow.
#include "coupling/dem_film_averages.hpp"
#include "coupling/film_mappings.hpp"

namespace centrec::coupling {

// Indices of the sections whose upstream edge lies at or past a.feed_end. Throws
// std::invalid_argument for a slice (one section: as_measured is its mapping) or a drum
// with no section past its feeder.
std::vector<std::size_t> sections_past_feeder(const DemFilmAverages& a);

// As a row of film_mappings(): the figures film_solid_fraction_cut and first_section_z_m,
// per section film_thickness (m) and flow_within_film_share.
FilmMappingResult map_film_along_drum(const DemFilmAverages& a);
// The same sections with each film's top where it carries kCarriedFlowShare of the section's
// flow (FilmTop::carried_flow): the sparse fast particles over the film inside it, as
// measured (phi and u of every bin up to there). Figures film_carried_flow_share and
// first_section_z_m.
FilmMappingResult map_film_along_drum_carried_flow(const DemFilmAverages& a);

}  // namespace centrec::coupling
