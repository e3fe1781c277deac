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
    const std::size_t slash = path.rfind('/');
    read_thermal_sections(root, slash == std::string::npos ? "" : path.substr(0, slash), t);
    c.thermal = std::move(t);
  }
  root.finish();
  c.resolved_yaml = root.resolved_text();
  return c;
}

}  // namespace centrec::cli
