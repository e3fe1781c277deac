#include "runs/dem_cache.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "io/atomic_write.hpp"
#include "io/provenance.hpp"

namespace centrec::runs {

namespace fs = std::filesystem;

std::string dem_cache_key(const std::string& resolved_dem_yaml, const config::DemCase& e, const std::string& version) {
  // The resolved section holds every key with its default; the values a receiver derives
  // (drum and flow) are not in it, so they are appended at full precision.
  char derived[256];
  std::snprintf(derived, sizeof derived, "\nderived: %.17g %.17g %.17g %.17g %.17g\n", e.scene.drum.diameter,
                e.scene.drum.length, e.scene.drum.omega, e.scene.drum.tilt, dem::scene::target_mass_flow(e.scene));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(io::fnv1a64(resolved_dem_yaml + derived + "version: " + version)));
  return hex;
}

std::string interrupted_dem_run(const std::string& cache_dir, const std::string& key) {
  std::error_code ec;
  if (!fs::is_directory(cache_dir, ec)) return {};
  const std::string prefix = key + ".tmp";
  for (const auto& e : fs::directory_iterator(cache_dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0 || !fs::exists(e.path() / "checkpoint.h5")) continue;
    const std::string pid_text = name.substr(prefix.size());
    if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(pid_text);
    // A live process still owns it (another `centrec run` of the same inputs): leave it alone.
    if (pid == static_cast<long>(::getpid()) || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    return e.path().string();
  }
  return {};
}

CachedDem cached_dem_run(const std::string& cache_dir, const std::string& key,
                         const std::function<void(const std::string& dir, bool resume)>& run) {
  CachedDem c;
  c.dir = cache_dir + "/" + key;
  if (fs::exists(c.dir + "/dem.h5") && fs::exists(c.dir + "/summary.json")) {
    c.hit = true;
    return c;
  }
  io::ensure_directory(cache_dir);
  const std::string tmp = c.dir + ".tmp" + std::to_string(::getpid());
  fs::remove_all(tmp);
  c.resumed_from = interrupted_dem_run(cache_dir, key);
  if (!c.resumed_from.empty()) fs::rename(c.resumed_from, tmp);
  run(tmp, !c.resumed_from.empty());
  fs::remove_all(c.dir);  // an incomplete entry
  fs::rename(tmp, c.dir);
  return c;
}

}  // namespace centrec::runs
