#include "dem_cache.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "atomic_write.hpp"

namespace centrec::cli {

namespace fs = std::filesystem;

namespace {
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}
}  // namespace

std::string dem_cache_key(const std::string& resolved_dem_yaml, const DemCase& e, const std::string& version) {
  // The resolved section holds every key with its default; the values a receiver derives
  // (drum and feed) are not in it, so they are appended at full precision.
  char derived[256];
  std::snprintf(derived, sizeof derived, "\nderived: %.17g %.17g %.17g %.17g %.17g\n", e.scene.drum.diameter,
                e.scene.drum.length, e.scene.drum.omega, e.scene.drum.tilt, e.scene.feeder.mass_flow);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a(resolved_dem_yaml + derived + "version: " + version)));
  return hex;
}

CachedDem cached_dem_run(const std::string& cache_dir, const std::string& key,
                         const std::function<void(const std::string& dir)>& run) {
  CachedDem c;
  c.dir = cache_dir + "/" + key;
  if (fs::exists(c.dir + "/dem.h5") && fs::exists(c.dir + "/summary.json")) {
    c.hit = true;
    return c;
  }
  ensure_directory(cache_dir);
  const std::string tmp = c.dir + ".tmp" + std::to_string(::getpid());
  fs::remove_all(tmp);
  run(tmp);
  fs::remove_all(c.dir);  // an incomplete entry
  fs::rename(tmp, c.dir);
  return c;
}

}  // namespace centrec::cli
