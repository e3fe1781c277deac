#pragma once
// The film mappings: each turns the DEM's averaged film (DemFilmAverages) into the thermal
// model's film field at the DEM's scale, and reports what it did in a form the outputs
// write without knowing the mapping (docs/coupling.md "Film mappings"). A mapping is a
// plain function in its own file and one row of film_mappings().
#include <string>
#include <vector>

#include "coupling/dem_film_averages.hpp"
#include "thermal/film_field.hpp"

namespace centrec::coupling {

// What a mapping reports: figures (one number each: a /coupling attribute of results.h5
// and a summary.json "coupling" entry) and profiles over the film's axial sections (a
// /coupling dataset; its minimum and maximum are summary figures when named).
struct FilmMappingReport {
  struct Figure {
    std::string name;  // snake_case, its unit in the name ("_m", "_kg_s") unless dimensionless
    double value = 0.0;
  };
  struct Profile {
    std::string name, unit;
    std::vector<double> values;  // per axial section of the film
    std::string min_as, max_as;  // summary figure names of its extremes ("" = not a figure)
  };
  std::string mapping;  // the mapping's name (film_mappings())
  std::vector<Figure> figures;
  std::vector<Profile> profiles;
  std::string text;  // one clause on the film for the run's report ("where phi >= 0.1 ...")

  // The figure or profile `name`; throws std::out_of_range naming it.
  double figure(const std::string& name) const;
  const std::vector<double>& profile(const std::string& name) const;
};

struct FilmMappingResult {
  thermal::FilmField film;  // DEM drum size; drum_diameter = 2 R of the DEM drum
  FilmMappingReport report;
};

struct FilmMappingEntry {
  const char* name;         // as a case or an output names it
  const char* description;  // one line: what film the thermal model receives
  FilmMappingResult (*map)(const DemFilmAverages&);  // throws std::invalid_argument naming the problem
};

// Every mapping, the default first.
const std::vector<FilmMappingEntry>& film_mappings();
// The mapping `name`; throws std::invalid_argument naming the known ones.
const FilmMappingEntry& film_mapping(const std::string& name);

}  // namespace centrec::coupling
