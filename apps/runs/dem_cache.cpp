#include "runs/dem_cache.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/atomic_write.hpp"
#include "io/provenance.hpp"
#include "runs/dem_inputs.hpp"

namespace centrec::runs {

namespace fs = std::filesystem;

std::string dem_cache_key(const std::string& resolved_yaml, const config::DemCase& e, const std::string& version) {
  // The resolved `dem:` section holds every key with its default (less those that change no
  // result: dem_inputs.hpp); the values a receiver derives (drum and flow) are not in it,
  // nor is a seed given on the command line (a replica), so they are appended at full
  // precision.
  std::string inputs;
  for (const auto& [key, value] : dem_input_values(resolved_yaml, {"dem"})) inputs += key + ": " + value + "\n";
  char derived[320];
  std::snprintf(derived, sizeof derived, "\nderived: %.17g %.17g %.17g %.17g %.17g\nseed: %llu\n", e.scene.drum.diameter,
                e.scene.drum.length, e.scene.drum.omega, e.scene.drum.tilt, dem::scene::target_mass_flow(e.scene),
                static_cast<unsigned long long>(e.scene.seed));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(io::fnv1a64(inputs + derived + "version: " + version)));
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

namespace {
constexpr const char* kChecksums = "checksums.txt";
const char* const kCheckedFiles[] = {"dem.h5", "summary.json"};

// Writes dir/checksums.txt: one "<file> <checksum>" line per file the coupled run reads back.
void write_checksums(const std::string& dir) {
  std::string text;
  for (const char* f : kCheckedFiles) text += std::string(f) + " " + io::file_checksum(dir + "/" + f) + "\n";
  io::write_text_atomically(dir + "/" + kChecksums, text);
}

// Throws naming the damaged file when a cached file differs from its recorded checksum.
void verify_checksums(const std::string& dir) {
  std::ifstream in(dir + "/" + kChecksums);
  std::string name, sum;
  int checked = 0;
  while (in >> name >> sum) {
    const std::string path = dir + "/" + name;
    const std::string now = io::file_checksum(path);
    if (now != sum)
      throw std::runtime_error(path + ": checksum mismatch (recorded " + sum + ", now " + now +
                               "): the cached DEM output is damaged; remove " + dir + " to run the DEM again");
    ++checked;
  }
  if (checked != static_cast<int>(std::size(kCheckedFiles)))
    throw std::runtime_error(dir + "/" + kChecksums + " is damaged; remove " + dir + " to run the DEM again");
}
}  // namespace

CachedDem cached_dem_run(const std::string& cache_dir, const std::string& key,
                         const std::function<void(const std::string& dir, bool resume)>& run) {
  CachedDem c;
  c.dir = cache_dir + "/" + key;
  // A complete entry has its checksums (written last); one without is rerun.
  if (fs::exists(c.dir + "/" + kChecksums)) {
    verify_checksums(c.dir);
    c.hit = true;
    return c;
  }
  const io::OutputFolder cache(cache_dir);  // removed again if this run leaves it empty
  const std::string tmp = c.dir + ".tmp" + std::to_string(::getpid());
  fs::remove_all(tmp);
  c.resumed_from = interrupted_dem_run(cache_dir, key);
  if (!c.resumed_from.empty()) fs::rename(c.resumed_from, tmp);
  try {
    run(tmp, !c.resumed_from.empty());
    write_checksums(tmp);
  } catch (...) {
    // Keep a folder with a checkpoint to continue from; remove one without.
    std::error_code ec;
    if (!fs::exists(tmp + "/checkpoint.h5", ec)) fs::remove_all(tmp, ec);
    throw;
  }
  fs::remove_all(c.dir);  // an incomplete entry
  fs::rename(tmp, c.dir);
  return c;
}

}  // namespace centrec::runs
