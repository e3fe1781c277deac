#include "dem/partner_routing.hpp"

#include <algorithm>
#include <cstddef>

namespace centrec::dem {

std::vector<long> split_by_weight(const std::vector<long>& weight, long parts) {
  const long blocks = static_cast<long>(weight.size());
  std::vector<long> before(static_cast<std::size_t>(blocks) + 1, 0);  // weight of blocks 0 .. b-1
  for (long b = 0; b < blocks; ++b) before[b + 1] = before[b] + weight[b];
  std::vector<long> start(static_cast<std::size_t>(parts) + 1, blocks);
  start[0] = 0;
  for (long p = 1; p < parts; ++p) {
    // The block boundary nearest to p / parts of the total (the lower one on a tie), never
    // below the previous start: the last b with before[b] x parts <= target, or the next.
    const long target = p * before[blocks];
    long b = start[p - 1];
    while (b < blocks && before[b + 1] * parts <= target) ++b;
    if (b < blocks && before[b + 1] * parts - target < target - before[b] * parts) ++b;
    start[p] = b;
  }
  return start;
}

PartnerRouting route_partner_shares(const NeighbourList& list, long block, long parts) {
  const long n = static_cast<long>(list.rows());
  const long blocks = (n + block - 1) / block;
  PartnerRouting out;
  out.parts = parts;
  // Per particle: the lowest and the highest row naming it (its own row if none does) and
  // how many entries name it.
  std::vector<long> first_reader(static_cast<std::size_t>(n)), last_reader(static_cast<std::size_t>(n));
  std::vector<std::uint32_t> named(static_cast<std::size_t>(n), 0);
  for (long j = 0; j < n; ++j) first_reader[static_cast<std::size_t>(j)] = last_reader[static_cast<std::size_t>(j)] = j;
  for (long i = 0; i < n; ++i)
    for (std::uint32_t e = list.start[i]; e < list.start[i + 1]; ++e) {
      const std::size_t j = static_cast<std::size_t>(list.nbr[e]);
      first_reader[j] = std::min(first_reader[j], i);
      last_reader[j] = std::max(last_reader[j], i);
      ++named[j];
    }
  // The pair pass's ranges: equal numbers of blocks. (Ranges of equal estimated cost, a
  // row's own work plus its entries, left the second thread the slower: its first rows
  // route their shares to parked slots; docs/benchmarks.md.)
  out.range_start.resize(static_cast<std::size_t>(parts) + 1);
  for (long p = 0; p <= parts; ++p) out.range_start[p] = first_block_of_part(blocks, parts, p);
  out.park_start.assign(static_cast<std::size_t>(n) + 1, 0);
  std::vector<long> parked_in_block(static_cast<std::size_t>(blocks), 0);
  for (long p = 0; p < parts; ++p)
    for (long j = out.range_start[p] * block; j < std::min(n, out.range_start[p + 1] * block); ++j) {
      // Parked: named by a row of an earlier range, or by a row after its own (a particle
      // taken into the list without a rebuild, dem/simulation_list_edits.cpp).
      const bool parked = first_reader[static_cast<std::size_t>(j)] < out.range_start[p] * block ||
                          last_reader[static_cast<std::size_t>(j)] > j;
      out.park_start[j + 1] = out.park_start[j] + (parked ? named[static_cast<std::size_t>(j)] : 0u);
      parked_in_block[j / block] += parked ? 1 : 0;
    }
  out.parked_range_start = split_by_weight(parked_in_block, parts);
  // Entries in increasing order are rows in increasing order: each parked group fills up in row order.
  std::vector<std::uint32_t> fill(out.park_start.begin(), out.park_start.end() - 1);
  out.slot.resize(list.nbr.size());
  for (std::size_t e = 0; e < list.nbr.size(); ++e) {
    const std::size_t j = static_cast<std::size_t>(list.nbr[e]);
    out.slot[e] = out.park_start[j] == out.park_start[j + 1] ? PartnerRouting::kDirect : fill[j]++;
  }
  return out;
}

}  // namespace centrec::dem
