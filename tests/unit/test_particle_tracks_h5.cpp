// The particle tracks on disk (apps/io/particle_tracks_h5.hpp): parts read back in snapshot
// order as written; the first part may start later than 0 (tracks begun by a resumed run);
// a gap between parts is refused naming the file; a resumed run's parts past its checkpoint
// are dropped.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/particle_tracks_h5.hpp"
#include "tests/test_case_dir.hpp"

namespace {
std::vector<centrec::io::TrackSnapshot> snapshots(double t0, int n) {
  std::vector<centrec::io::TrackSnapshot> out;
  for (int k = 0; k < n; ++k) {
    centrec::io::TrackSnapshot s;
    s.time = t0 + 0.1 * k;
    for (int i = 0; i < 3 + k; ++i) {
      s.id.push_back(100 + i);
      s.z.push_back(0.01 * i + s.time);
      s.r.push_back(0.04 - 1e-4 * i);
    }
    out.push_back(s);
  }
  return out;
}
}  // namespace

TEST(ParticleTracksH5, PartsReadBackInOrderAndAGapIsRefused) {
  const std::string dir = centrec::testing::fresh_dir("tracks_h5");
  centrec::io::write_track_part(dir, 5, snapshots(1.0, 2));  // snapshots 5, 6
  centrec::io::write_track_part(dir, 7, snapshots(1.2, 3));  // 7, 8, 9
  const auto t = centrec::io::read_tracks(dir);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_DOUBLE_EQ(t[2].time, 1.2);
  EXPECT_EQ(t[4].id.size(), 5u);
  EXPECT_DOUBLE_EQ(t[4].z[4], 0.04 + 1.4);
  // A part that leaves snapshots 10-11 out.
  centrec::io::write_track_part(dir, 12, snapshots(1.7, 1));
  try {
    centrec::io::read_tracks(dir);
    ADD_FAILURE() << "a gap between parts was read";
  } catch (const std::runtime_error& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("part_0000012.h5"), std::string::npos);
  }
  // A run resumed from the checkpoint at snapshot 7 takes 7 on again.
  centrec::io::drop_track_parts_from(dir, 7);
  EXPECT_EQ(centrec::io::read_tracks(dir).size(), 2u);
  std::filesystem::remove_all(dir);
}
