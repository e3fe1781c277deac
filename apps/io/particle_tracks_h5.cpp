#include "io/particle_tracks_h5.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "io/h5_file.hpp"

namespace centrec::io {

namespace fs = std::filesystem;

namespace {

const char* const kFormat = "centrec particle tracks 1";

// DIR/tracks/part_NNNNNNN.h5 -> NNNNNNN; -1 for another name.
std::int64_t part_index(const fs::path& p) {
  const std::string name = p.filename().string();
  long long k = -1;
  char tail[8] = {0};
  if (std::sscanf(name.c_str(), "part_%lld%7s", &k, tail) != 2 || std::string(tail) != ".h5" || k < 0) return -1;
  return k;
}

std::map<std::int64_t, fs::path> parts_in(const std::string& run_dir) {
  std::map<std::int64_t, fs::path> parts;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(tracks_dir(run_dir), ec))
    if (const std::int64_t k = part_index(e.path()); k >= 0) parts[k] = e.path();
  return parts;
}

}  // namespace

std::string tracks_dir(const std::string& run_dir) { return run_dir + "/tracks"; }

void write_track_part(const std::string& run_dir, std::int64_t first_index, const std::vector<TrackSnapshot>& snaps) {
  if (snaps.empty()) return;
  fs::create_directories(tracks_dir(run_dir));
  char name[40];
  std::snprintf(name, sizeof name, "/part_%07lld.h5", static_cast<long long>(first_index));
  H5File f = H5File::create(tracks_dir(run_dir) + name);
  f.set_attribute("/", "format", kFormat);
  f.set_attribute("/", "first_snapshot", static_cast<double>(first_index));
  // Snapshot k's particles are entries offset[k] .. offset[k + 1] - 1 of id, z and r.
  std::vector<double> time, z, r;
  std::vector<std::int64_t> offset{0}, id;
  for (const TrackSnapshot& s : snaps) {
    time.push_back(s.time);
    id.insert(id.end(), s.id.begin(), s.id.end());
    z.insert(z.end(), s.z.begin(), s.z.end());
    r.insert(r.end(), s.r.begin(), s.r.end());
    offset.push_back(static_cast<std::int64_t>(id.size()));
  }
  f.write("/time", time, "s");
  f.write_int64("/offset", offset, {offset.size()}, "1");
  f.write_int64("/id", id, {id.size()}, "1");
  f.write("/z", z, "m");
  f.write("/r", r, "m");
  f.commit();
}

void drop_track_parts_from(const std::string& run_dir, std::int64_t first_index) {
  for (const auto& [k, path] : parts_in(run_dir))
    if (k >= first_index) fs::remove(path);
}

std::vector<TrackSnapshot> read_tracks(const std::string& run_dir) {
  std::vector<TrackSnapshot> out;
  std::int64_t next = -1;  // the first part may start later than 0 (tracks begun in a resumed run)
  for (const auto& [k, path] : parts_in(run_dir)) {
    try {
      const H5File f = H5File::open_read(path.string());
      if (!f.has_attribute("/", "format") || f.string_attribute("/", "format") != kFormat)
        throw std::runtime_error(std::string("not a ") + kFormat + " file");
      if (next >= 0 && k != next)
        throw std::runtime_error("starts at snapshot " + std::to_string(k) + " where the parts before end at " +
                                 std::to_string(next));
      const std::vector<double> time = f.read("/time"), offset = f.read("/offset"), id = f.read("/id"),
                                z = f.read("/z"), r = f.read("/r");
      if (offset.size() != time.size() + 1 || offset.front() != 0.0 ||
          offset.back() != static_cast<double>(id.size()) || z.size() != id.size() || r.size() != id.size())
        throw std::runtime_error("inconsistent dataset sizes");
      for (std::size_t s = 0; s < time.size(); ++s) {
        const auto a = static_cast<std::size_t>(offset[s]), b = static_cast<std::size_t>(offset[s + 1]);
        if (b < a || b > id.size()) throw std::runtime_error("offsets out of order");
        TrackSnapshot t;
        t.time = time[s];
        for (std::size_t i = a; i < b; ++i) t.id.push_back(static_cast<std::int64_t>(id[i]));
        t.z.assign(z.begin() + static_cast<std::ptrdiff_t>(a), z.begin() + static_cast<std::ptrdiff_t>(b));
        t.r.assign(r.begin() + static_cast<std::ptrdiff_t>(a), r.begin() + static_cast<std::ptrdiff_t>(b));
        out.push_back(std::move(t));
      }
      next = k + static_cast<std::int64_t>(time.size());
    } catch (const std::exception& e) {
      throw std::runtime_error("particle tracks " + path.string() + ": " + e.what());
    }
  }
  return out;
}

}  // namespace centrec::io
