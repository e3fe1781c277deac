#pragma once
// A fed drum's particle tracks on disk (docs/outputs.md "Particle tracks"; the record is
// dem/film/particle_tracks.hpp): every sampled snapshot, at the samplers' rate
// (dem.sampling.snapshots_per_turn), which dem.h5's snapshots thin out for a long run.
// Written in parts, one per checkpoint, so hours of sampling survive an interrupted run:
// DIR/tracks/part_NNNNNNN.h5, named by the index of its first snapshot counted from the
// start of sampling.
#include <cstdint>
#include <string>
#include <vector>

#include "dem/film/particle_tracks.hpp"

namespace centrec::io {

using film::TrackSnapshot;

std::string tracks_dir(const std::string& run_dir);

// Writes `snaps` (snapshots first_index, first_index + 1, ...) as one part, atomically.
void write_track_part(const std::string& run_dir, std::int64_t first_index, const std::vector<TrackSnapshot>& snaps);

// Removes the parts that start at or after `first_index`: snapshots a run that resumes from
// an earlier checkpoint takes again.
void drop_track_parts_from(const std::string& run_dir, std::int64_t first_index);

// All parts in snapshot order, from the first part on disk (a run resumed from a
// checkpoint of a binary that wrote no tracks starts them there). Throws
// std::runtime_error on a gap or an overlap between parts, or on a damaged part (naming
// the file).
std::vector<TrackSnapshot> read_tracks(const std::string& run_dir);

}  // namespace centrec::io
