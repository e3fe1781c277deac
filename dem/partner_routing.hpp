#pragma once
// The force pass's row ranges, one per thread, and where it puts the partner's share of
// each pair (force and torque on j, the partner of row i's half-list entry (i, j)).
//
// Rows are worked on in `parts` contiguous ranges of blocks, one thread each. A partner
// whose every naming row lies in its own range is "direct": its rows add their shares
// straight into its accumulator, in increasing row order, before its own row reads and
// clears it. A partner named by a row of another range (the first rows of a range, and any
// named round a periodic boundary) is "parked": its shares are written to slots grouped by
// partner in the same increasing row order, and summed once all ranges are done. Both give
// the sum of the shares in increasing row order, then plus the partner's own row: the same
// bits for any number of parts and wherever the ranges start. A row may also name a
// partner of lower index (a particle taken in without a rebuild names older ones): that
// partner is parked too, so it is totalled only after the row that names it last.
//
// Speed: the pair pass's ranges hold equal numbers of blocks; the parked particles all lie
// in the ranges after the first, so the parked pass has ranges of its own, with equal
// numbers of them, and the threads finish it together (docs/benchmarks.md).
#include <cstdint>
#include <limits>
#include <vector>

#include "dem/neighbour_list.hpp"

namespace centrec::dem {

struct PartnerRouting {
  static constexpr std::uint32_t kDirect = std::numeric_limits<std::uint32_t>::max();
  long parts = 0;                         // row ranges planned for (0: not planned)
  std::vector<long> range_start;          // parts + 1 blocks: the pair pass's range p is blocks [range_start[p], range_start[p + 1])
  std::vector<long> parked_range_start;   // parts + 1 blocks: the parked pass's ranges (split_by_weight)
  std::vector<std::uint32_t> slot;        // per list entry: kDirect or its parked slot
  std::vector<std::uint32_t> park_start;  // rows + 1: j's parked slots are [park_start[j], park_start[j + 1])
  std::size_t parked() const { return park_start.empty() ? 0 : park_start.back(); }
};

// First block of range p of `parts` over `blocks` blocks (the pair pass's ranges).
inline long first_block_of_part(long blocks, long parts, long p) { return blocks * p / parts; }

// Splits blocks 0 .. weight.size() - 1 into `parts` contiguous ranges of about equal total
// weight: range p starts at the block boundary where the weight before it is nearest to
// p / parts of the total (the lower one on a tie). Returns parts + 1 starts.
std::vector<long> split_by_weight(const std::vector<long>& weight, long parts);

// Row ranges and routing for the list's rows in blocks of `block` rows, `parts` threads.
PartnerRouting route_partner_shares(const NeighbourList& list, long block, long parts);

}  // namespace centrec::dem
