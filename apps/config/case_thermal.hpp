#pragma once
// The thermal case: YAML -> typed thermal config structs (docs/architecture.md and docs/thermal_model.md). Top-level
// keys `title`, `film` ({analytic: ...} or {file: ..., group: ...}) and `thermal`. Every key
// is checked for type and range by the strict reader; relations between keys (thickness
// above one particle diameter, ...) are refused with the key path and line.
#include <string>

#include "config/strict_yaml.hpp"
#include "thermal/film_field.hpp"
#include "thermal/film_model.hpp"
#include "thermal/steady_state.hpp"
#include "thermal/transient_run.hpp"

namespace centrec::config {

struct ThermalCase {
  std::string path, title;
  thermal::FilmField film;
  std::string film_source;  // "analytic" or the HDF5 file it was read from
  std::string particle;     // thermal.particle: the name in thermal/particle_data.hpp
  thermal::FilmModel model;
  thermal::FilmGridSpec grid;
  thermal::SteadySettings steady;
  bool transient = false;
  thermal::TransientSettings transient_settings;
  std::string resolved_yaml;
};

// Reads the sections `film` and `thermal` from a root reader (shared by other case readers).
// With film_from_dem, a missing `film` section is allowed: the coupled run supplies the film
// (film_source "dem").
void read_thermal_sections(MapReader& root, const std::string& case_dir, ThermalCase& c,
                           bool film_from_dem = false);
// Folder of a case file, against which its relative file paths resolve ("" = cwd).
std::string case_directory(const std::string& case_path);
// Reads a whole thermal case file; throws ConfigError on the first problem.
ThermalCase read_thermal_case(const std::string& path);

}  // namespace centrec::config
