#include "config/case_file.hpp"

namespace centrec::config {

namespace {

CaseFile read_case(MapReader root, const std::string& path) {
  CaseFile c;
  c.path = path;
  c.title = root.string("title", "");
  root.string("description", "");
  if (root.has("dem")) c.dem = read_dem_case(root.child("dem"));
  if (root.has("receiver")) {
    if (!c.dem) root.fail("receiver", "a receiver is simulated through a scaled-down `dem:` section; add one");
    c.receiver = read_receiver(root.child("receiver"), root.child("dem"));
  }
  if (root.has("film") || root.has("thermal")) {
    ThermalCase t;
    t.path = path;
    t.title = c.title;
    // In a coupled case (with `dem:`) the film comes from the DEM, so `film:` is optional.
    read_thermal_sections(root, case_directory(path), t, c.dem.has_value());
    c.thermal = std::move(t);
  }
  if (root.has("sweep")) c.sweep = read_sweep(root.child("sweep"));
  root.finish();
  c.resolved_yaml = root.resolved_text();
  return c;
}

}  // namespace

CaseFile read_case_file(const std::string& path) { return read_case(MapReader::from_file(path), path); }

CaseFile read_case_text(const std::string& text, const std::string& path) {
  return read_case(MapReader::from_string(text, path), path);
}

}  // namespace centrec::config
