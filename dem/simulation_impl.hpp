#pragma once
// Private state of Simulation shared by its implementation files (simulation.cpp: set-up,
// particles, lists, integration; simulation_forces.cpp: the force pass). Not public API.
#include <cstdint>
#include <string>
#include <vector>

#include "dem/neighbour_list.hpp"
#include "dem/periodic_z.hpp"
#include "dem/simulation.hpp"

namespace centrec::dem {

// Particles are processed in fixed blocks so that per-wall force sums and statistics are
// reduced in an order independent of the thread count (bitwise determinism).
inline constexpr long kBlock = 256;
// State size above which the gather pass fetches ahead. Film scan of 2026-11-23 (1 thread):
// 6.75e6 particle-steps/s at 1e4 particles (8.7 MB), 5.46e6 at 2e4 (16 MB), so the state
// leaves this host's cache in between. On 2026-12-01 the fetch-ahead, done at every size,
// cost 5 % at 1e4 (6.6-7.0e6 against 7.2-7.3e6 without, three alternating rounds) and on
// the quickstart's DEM, and gained 0-13 % at 2e5 (tests/bench/README.md).
inline constexpr std::size_t kGatherFetchAheadBytes = std::size_t{12} << 20;
inline constexpr int kMaxWalls = 32;  // wall candidates are a 32-bit mask per particle

struct BlockTally {
  std::vector<Vec3> wall_force;  // one per wall
  std::size_t pair_contacts = 0, wall_contacts = 0;
  long blowup_index = -1;  // first offending particle of the block
  Vec3 blowup_x;           // its position then
  double blowup_overlap = 0.0;
  std::string blowup_partner;
};

struct Simulation::Impl {
  NeighbourList list;              // valid while !dirty_
  NeighbourList carried;           // while dirty_: the contacts to carry into the next rebuild
  CellGrid grid;
  PeriodicZ pz;
  double skin = 0.0;
  std::vector<Vec3> x_build;                // positions at the last rebuild
  // Displacements are measured in the drum's rotating frame when the whole scene is
  // symmetric about the drum axis (pair distances and wall gaps do not change under the
  // rigid rotation), so a co-rotating film does not trigger rebuilds at omega R / skin.
  bool drum_frame = false;
  double angle_since_build = 0.0;
  std::vector<ContactHistory> wall_hist;    // N x walls
  std::vector<std::uint32_t> wall_mask;     // candidate walls per particle
  std::vector<BlockTally> tallies;
  // Per list entry, written in force pass 1 and gathered in pass 2.
  std::vector<std::uint8_t> touch;  // in contact at the last force pass (then hist may be non-zero)
  struct PartnerShare {
    Vec3 force, torque;
  };
  // The partner's share of force and torque, at the entry's reverse position (list.rev_pos)
  // so pass 2 reads it sequentially; zero while the entry is not in contact.
  std::vector<PartnerShare> share;
  // Set at each rebuild: the state is larger than what the last-level cache holds for it,
  // so the gather pass fetches ahead (in cache the extra instructions only cost).
  bool gather_fetch_ahead = false;
  std::size_t rebuilds = 0, pair_contacts = 0, wall_contacts = 0;
};

}  // namespace centrec::dem
