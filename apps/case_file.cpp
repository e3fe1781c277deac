#include "case_file.hpp"

namespace centrec::cli {

CaseFile read_case_file(const std::string& path) {
  auto root = yaml::MapReader::from_file(path);
  CaseFile c;
  c.path = path;
  c.title = root.string("title", "");
  root.string("description", "");
  if (root.has("dem")) c.dem = read_dem_case(root.child("dem"));
  if (root.has("film") || root.has("thermal")) {
    ThermalCase t;
    t.path = path;
    t.title = c.title;
    read_thermal_sections(root, case_directory(path), t);
    c.thermal = std::move(t);
  }
  root.finish();
  c.resolved_yaml = root.resolved_text();
  return c;
}

}  // namespace centrec::cli
