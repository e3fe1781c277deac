#pragma once
// Reading LIGGGHTS `dump custom` files (one snapshot per file) into the samplers'
// particle columns (film::ParticleColumns), so LIGGGHTS results feed the same film
// samplers as the native engine. Needs the columns id radius x y z vx vy vz (any order,
// extra columns ignored).
#include <cstdint>
#include <string>
#include <vector>

#include "dem/scene/scene_sampler.hpp"

namespace centrec::liggghts {

// Reads one dump file; time = its timestep x dt. Throws std::runtime_error naming the
// file and line on a malformed or truncated file.
dem::scene::SnapshotArrays read_liggghts_dump(const std::string& path, double dt);

// The timestep of a dump file named PREFIX<step>SUFFIX by `dump ... film_*.dump`, or -1.
std::int64_t dump_file_step(const std::string& file_name);

// Dump files in dir whose names match prefix*suffix, sorted by timestep.
std::vector<std::string> list_dump_files(const std::string& dir, const std::string& prefix,
                                         const std::string& suffix);

}  // namespace centrec::liggghts
