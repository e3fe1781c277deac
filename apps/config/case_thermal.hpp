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

// Where a thermal case's film comes from: the analytic film of `film: {analytic:}`, a stored
// film field (`film: {file:}`), or a coupled run's DEM through a film mapping
// (coupling/film_mappings.hpp).
struct FilmSource {
  enum class Kind { analytic, file, dem };
  Kind kind = Kind::analytic;
  std::string file;  // file: the film field read; dem: the dem.h5 mapped ("" until the coupled run sets it)
  std::string mapping;  // dem: the film mapping's name (default: the registry's first, coupling/film_mappings.hpp)

  bool from_dem() const { return kind == Kind::dem; }
  // As the outputs record it: "analytic", the file, "dem" or "dem: <dem.h5>".
  std::string text() const;
};

struct ThermalCase {
  std::string path, title;
  thermal::FilmField film;
  FilmSource film_source;
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
// (FilmSource::Kind::dem).
void read_thermal_sections(MapReader& root, const std::string& case_dir, ThermalCase& c,
                           bool film_from_dem = false);
// Folder of a case file, against which its relative file paths resolve ("" = cwd).
std::string case_directory(const std::string& case_path);
// Reads a whole thermal case file; throws ConfigError on the first problem.
ThermalCase read_thermal_case(const std::string& path);
struct CaseFile;
// The thermal case of a case file read already (with command-line values, say); throws
// ConfigError when it has none or its film comes from its DEM (`centrec run`).
ThermalCase thermal_case_of(const CaseFile& cf);

}  // namespace centrec::config
