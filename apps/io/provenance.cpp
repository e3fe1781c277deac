#include "io/provenance.hpp"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>

#include "io/code_version.hpp"

namespace centrec::io {

std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "unreadable";
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  char buf[40];
  std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(fnv1a64(bytes)));
  return buf;
}

void write_provenance(H5File& f, const Provenance& p) {
  f.set_attribute("/", "code_version", code_version());
  f.set_attribute("/", "case", p.case_path);
  f.set_attribute("/", "resolved_config", p.resolved_config);
  std::string hashes;
  for (const auto& file : p.input_files) hashes += file_hash(file) + "  " + file + "\n";
  f.set_attribute("/", "input_hashes", hashes);
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &utc);
  f.set_attribute("/", "written_utc", when);
}

}  // namespace centrec::io
