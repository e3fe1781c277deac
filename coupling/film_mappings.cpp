#include "coupling/film_mappings.hpp"

#include <stdexcept>

#include "coupling/film_along_drum.hpp"
#include "coupling/film_mapping.hpp"

namespace centrec::coupling {

double FilmMappingReport::figure(const std::string& name) const {
  for (const Figure& f : figures)
    if (f.name == name) return f.value;
  throw std::out_of_range("film mapping report: no figure '" + name + "'");
}

const std::vector<double>& FilmMappingReport::profile(const std::string& name) const {
  for (const Profile& p : profiles)
    if (p.name == name) return p.values;
  throw std::out_of_range("film mapping report: no profile '" + name + "'");
}

const std::vector<FilmMappingEntry>& film_mappings() {
  static const std::vector<FilmMappingEntry> table = {
      {"as_measured_carried_flow",
       "as as_measured, the film reaching up to where it carries 99.5 % of the DEM's flow (the loose top inside it; "
       "docs/coupling.md \"Film as measured\")",
       map_film_as_measured_carried_flow},
      {"as_measured",
       "the film as the DEM measured it: full-circumference profiles of the developed sections, cut where the solid "
       "fraction falls below 0.1 (docs/coupling.md \"Film as measured\")",
       map_film_as_measured},
      {"along_drum",
       "a fed drum's film section by section along z from the feeder's end to the outlet, each section's own "
       "profiles, cut where the solid fraction crosses 0.1 (docs/coupling.md \"Film along the drum\")",
       map_film_along_drum},
      {"along_drum_carried_flow",
       "as along_drum, each section's film reaching up to where it carries 99.5 % of the section's flow: the sparse, "
       "fast particles over the film (a fed drum's feed stream) inside it, as measured (docs/coupling.md \"Film along "
       "the drum\")",
       map_film_along_drum_carried_flow},
  };
  return table;
}

const FilmMappingEntry& film_mapping(const std::string& name) {
  std::string known;
  for (const FilmMappingEntry& e : film_mappings()) {
    if (e.name == name) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw std::invalid_argument("no film mapping '" + name + "' (known: " + known + ")");
}

}  // namespace centrec::coupling
