#include "dem/partner_routing.hpp"

#include <algorithm>

namespace centrec::dem {

PartnerRouting route_partner_shares(const NeighbourList& list, long block, long parts) {
  const long n = static_cast<long>(list.rows());
  PartnerRouting out;
  out.parts = parts;
  // Per particle: the lowest row naming it (its own row if none does) and how many entries name it.
  std::vector<long> first_reader(static_cast<std::size_t>(n));
  std::vector<std::uint32_t> named(static_cast<std::size_t>(n), 0);
  for (long j = 0; j < n; ++j) first_reader[static_cast<std::size_t>(j)] = j;
  for (long i = 0; i < n; ++i)
    for (std::uint32_t e = list.start[i]; e < list.start[i + 1]; ++e) {
      const std::size_t j = static_cast<std::size_t>(list.nbr[e]);
      first_reader[j] = std::min(first_reader[j], i);
      ++named[j];
    }
  const long blocks = (n + block - 1) / block;
  out.park_start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (long p = 0; p < parts; ++p) {
    const long row0 = first_block_of_part(blocks, parts, p) * block;
    const long row1 = std::min(n, first_block_of_part(blocks, parts, p + 1) * block);
    for (long j = row0; j < row1; ++j) {
      const bool parked = first_reader[static_cast<std::size_t>(j)] < row0;
      out.park_start[j + 1] = out.park_start[j] + (parked ? named[static_cast<std::size_t>(j)] : 0u);
    }
  }
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
