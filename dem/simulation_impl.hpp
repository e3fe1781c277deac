#pragma once
// Private state of Simulation shared by its implementation files (simulation.cpp: set-up,
// particles, lists, integration; simulation_forces.cpp: the force pass). Not public API.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dem/neighbour_list.hpp"
#include "dem/partner_routing.hpp"
#include "dem/periodic_z.hpp"
#include "dem/simulation.hpp"
#include "dem/thread_team.hpp"

namespace centrec::dem {

// Particles are processed in fixed blocks so that per-wall force sums and statistics are
// reduced in an order independent of the thread count (bitwise determinism).
inline constexpr long kBlock = 256;
inline constexpr int kMaxWalls = 32;  // wall candidates are a 32-bit mask per particle

// Rows of `width` elements: row k of the result is row order[k] of a (the order may be
// shorter than a's rows: the rows it leaves out are dropped).
// Speed: the result is built in a spare array kept per element type and thread, which then
// trades storage with `a`, so the spare holds a's old storage for the next permutation: a
// re-sort of a fed drum (~300 bytes per particle over all arrays) faults in no fresh pages.
template <class T>
void permute_rows(std::vector<T>& a, const std::vector<std::int32_t>& order, std::size_t width = 1) {
  static thread_local std::vector<T> spare;
  spare.resize(order.size() * width);
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t c = 0; c < width; ++c) spare[k * width + c] = a[static_cast<std::size_t>(order[k]) * width + c];
  a.swap(spare);
}

// Speed: a free particle's half-skin (ListSlack) is at least skin/2 and at most a
// diameter, and reaches as far as the particle flies at its speed at the build in this many
// steps. A drum's film moves slowly in the drum's frame, while a few particles (fed ones
// falling through the drum's hollow, those thrown off the film's top) cross it at 1-1.4
// m/s; with one skin for all they forced a rebuild every ~9 steps (docs/benchmarks.md).
// Those few now get lists that reach further, found in a wider block of cells.
inline constexpr double kListHorizonSteps = 30.0;

struct BlockTally {
  std::vector<Vec3> wall_force;  // one per wall
  std::size_t pair_contacts = 0, wall_contacts = 0;
  long blowup_index = -1;  // first offending particle of the block
  Vec3 blowup_x;           // its position then
  double blowup_overlap = 0.0;
  std::string blowup_partner;

  void reset(std::size_t walls) {
    wall_force.assign(walls, Vec3{});
    pair_contacts = wall_contacts = 0;
    blowup_index = -1;
  }
  // Keeps the block's first blow-up: particle i at x, its overlap (NaN: a non-finite
  // state) and what it overlaps (partner(), a string, built only for the first).
  template <class Partner>
  void note_blow_up(long i, Vec3 x, double overlap, Partner partner) {
    if (blowup_index >= 0) return;
    blowup_index = i;
    blowup_x = x;
    blowup_overlap = overlap;
    blowup_partner = partner();
  }
};

// A partner's share of one pair, parked until the parked pass sums it (partner_routing.hpp).
struct PartnerShare {
  Vec3 force, torque;
};

struct Simulation::Impl {
  std::unique_ptr<ThreadTeam> team;  // threads_ threads (set_threads)
  NeighbourList list;              // valid while !dirty_
  NeighbourList carried;           // while dirty_: the contacts to carry into the next rebuild
  // Speed: a rebuild's scratch, kept between rebuilds so none faults in fresh pages.
  NeighbourList carry_buffer;      // the contacts carried into the list being built
  ListBuildScratch build_scratch;
  CellGrid grid;
  PeriodicZ pz;
  double skin = 0.0;
  std::vector<Vec3> x_build;                // positions at the last rebuild
  std::vector<double> half_skin;            // per particle, set at the last rebuild (ListSlack)
  // Displacements are measured in the drum's rotating frame when the whole scene is
  // symmetric about the drum axis (pair distances and wall gaps do not change under the
  // rigid rotation), so a co-rotating film does not trigger rebuilds at omega R / skin.
  bool drum_frame = false;
  double angle_since_build = 0.0;
  std::vector<std::uint32_t> wall_mask;     // candidate walls per particle
  std::vector<BlockTally> tallies;
  std::vector<std::uint8_t> touch;  // per list entry: in contact at the last force pass (then hist may be non-zero)
  // Partner shares (see partner_routing.hpp): planned for the force pass's row ranges after
  // each rebuild; the direct ones go to acc_f / acc_t (zero outside the pair pass), the
  // parked ones to `share` (grouped by partner; zero while the entry is not in contact).
  PartnerRouting routing;
  std::vector<Vec3> acc_f, acc_t;
  std::vector<PartnerShare> share;
  std::size_t rebuilds = 0, list_edits = 0, pair_contacts = 0, wall_contacts = 0;
};

}  // namespace centrec::dem
