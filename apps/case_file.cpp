#include "case_file.hpp"

namespace centrec::cli {

namespace {

CaseFile read_case(yaml::MapReader root, const std::string& path) {
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

}  // namespace

CaseFile read_case_file(const std::string& path) { return read_case(yaml::MapReader::from_file(path), path); }

CaseFile read_case_text(const std::string& text, const std::string& path) {
  return read_case(yaml::MapReader::from_string(text, path), path);
}

}  // namespace centrec::cli
