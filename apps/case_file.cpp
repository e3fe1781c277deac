#include "case_file.hpp"

namespace centrec::cli {

CaseFile read_case_file(const std::string& path) {
  auto root = yaml::MapReader::from_file(path);
  CaseFile c;
  c.path = path;
  c.title = root.string("title", "");
  root.string("description", "");
  if (root.has("dem")) c.dem = read_dem_case(root.child("dem"));
  root.finish();
  c.resolved_yaml = root.resolved_text();
  return c;
}

}  // namespace centrec::cli
