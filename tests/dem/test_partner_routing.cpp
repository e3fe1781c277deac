// Routing of the partner shares (dem/partner_routing.hpp): with the rows worked on in one
// range every partner is summed directly; with more ranges exactly the partners named by a
// row of another range (a range's first particles, and across a periodic boundary) are
// parked, in slots grouped by partner in increasing row order.
#include <gtest/gtest.h>

#include <vector>

#include "dem/partner_routing.hpp"
#include "periodic_chain.hpp"

using namespace centrec::dem;

namespace {

// The list of a touching chain round a period of length n: row k names k + 1, row 0 also
// names n - 1.
NeighbourList chain_list(int n) {
  const centrec::dem::testing::PeriodicChain c = centrec::dem::testing::periodic_chain(n);
  CellGrid grid;
  const std::vector<std::int32_t> order = sort_into_cells(grid, c.x, 1.1, c.pz);
  for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], static_cast<std::int32_t>(k));
  NeighbourList list;
  ThreadTeam serial(1);
  ListBuildScratch scratch;
  build_neighbour_list(list, grid, c.x, c.r, c.motion, 0.1, {}, c.pz, NeighbourList{}, serial, scratch);
  return list;
}

// Slot of the entry of row i naming j.
std::uint32_t slot_of(const NeighbourList& list, const PartnerRouting& routing, int i, int j) {
  for (std::uint32_t e = list.start[i]; e < list.start[i + 1]; ++e)
    if (list.nbr[e] == j) return routing.slot[e];
  ADD_FAILURE() << "no entry " << i << " -> " << j;
  return 0;
}

std::vector<int> parked_particles(const PartnerRouting& routing) {
  std::vector<int> out;
  for (std::size_t j = 0; j + 1 < routing.park_start.size(); ++j)
    if (routing.park_start[j] != routing.park_start[j + 1]) out.push_back(static_cast<int>(j));
  return out;
}

}  // namespace

TEST(PartnerRouting, OneRangeSumsEveryPartnerDirectly) {
  const NeighbourList list = chain_list(1000);
  ASSERT_EQ(list.nbr.size(), 1000u);
  const PartnerRouting routing = route_partner_shares(list, 100, 1);
  EXPECT_EQ(routing.parked(), 0u);
  for (std::uint32_t s : routing.slot) EXPECT_EQ(s, PartnerRouting::kDirect);
}

TEST(PartnerRouting, PartnersNamedFromAnotherRangeAreParkedInRowOrder) {
  const NeighbourList list = chain_list(1000);
  // 10 blocks of 100 rows; 2 ranges: rows 0-499 and 500-999. Particle 500 is named by row
  // 499, particle 999 by rows 0 (across the period) and 998.
  const PartnerRouting two = route_partner_shares(list, 100, 2);
  EXPECT_EQ(parked_particles(two), (std::vector<int>{500, 999}));
  ASSERT_EQ(two.parked(), 3u);
  EXPECT_EQ(slot_of(list, two, 499, 500), two.park_start[500]);
  EXPECT_EQ(slot_of(list, two, 0, 999), two.park_start[999]);      // lower row first
  EXPECT_EQ(slot_of(list, two, 998, 999), two.park_start[999] + 1);
  EXPECT_EQ(slot_of(list, two, 500, 501), PartnerRouting::kDirect);
  EXPECT_EQ(slot_of(list, two, 0, 1), PartnerRouting::kDirect);
  // The parked pass splits the parked particles evenly: 500 (block 5) and 999 (block 9).
  EXPECT_EQ(two.parked_range_start, (std::vector<long>{0, 9, 10}));
  // 3 ranges start at blocks 0, 3 and 6 (10 x p / 3).
  const PartnerRouting three = route_partner_shares(list, 100, 3);
  EXPECT_EQ(three.range_start, (std::vector<long>{0, 3, 6, 10}));
  EXPECT_EQ(parked_particles(three), (std::vector<int>{300, 600, 999}));
  EXPECT_EQ(three.parked(), 4u);
  // The parked pass: one parked particle in each of blocks 3, 6 and 9.
  EXPECT_EQ(three.parked_range_start, (std::vector<long>{0, 6, 9, 10}));
}

TEST(PartnerRouting, RangesSplitTheWeightAtTheNearestBlockBoundary) {
  // Weights 1 1 1 1 10 1 1 1 1 1 (total 19): before block 5 lie 14, before block 4 lie 4;
  // 14 is nearer to half (9.5).
  EXPECT_EQ(split_by_weight({1, 1, 1, 1, 10, 1, 1, 1, 1, 1}, 2), (std::vector<long>{0, 5, 10}));
  EXPECT_EQ(split_by_weight({3, 3, 3, 3}, 4), (std::vector<long>{0, 1, 2, 3, 4}));
  EXPECT_EQ(split_by_weight({0, 0, 0, 0}, 2), (std::vector<long>{0, 4, 4}));  // nothing to share
  EXPECT_EQ(split_by_weight({5, 5}, 3), (std::vector<long>{0, 1, 1, 2}));   // more ranges than blocks
}
