#include "neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::dem {

std::size_t NeighbourList::bytes() const {
  return start.capacity() * sizeof(std::uint32_t) +
         nbr.capacity() * sizeof(std::int32_t) + hist.capacity() * sizeof(ContactHistory);
}

void carry_contacts(const NeighbourList& old, const std::vector<std::int32_t>& order,
                    const std::vector<std::int32_t>& new_of_old, NeighbourList& out) {
  out.start.assign(order.size() + 1, 0);
  out.nbr.clear();
  out.hist.clear();
  out.reach = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t o = static_cast<std::size_t>(order[k]);
    if (o < old.rows()) {
      for (std::uint32_t e = old.start[o]; e < old.start[o + 1]; ++e) {
        const std::int32_t j = new_of_old[static_cast<std::size_t>(old.nbr[e])];
        if (j < 0 || is_zero(old.hist[e])) continue;
        out.nbr.push_back(j);
        out.hist.push_back(old.hist[e]);
      }
    }
    out.start[k + 1] = static_cast<std::uint32_t>(out.nbr.size());
  }
}

long CellGrid::cell_of(Vec3 x) const {
  auto clampi = [](long v, int n) { return v < 0 ? 0L : (v >= n ? static_cast<long>(n) - 1 : v); };
  const long ix = clampi(static_cast<long>((x.x - lo.x) * inv_cx), nx);
  const long iy = clampi(static_cast<long>((x.y - lo.y) * inv_cy), ny);
  const long iz = clampi(static_cast<long>((x.z - lo.z) * inv_cz), nz);
  return ix + nx * (iy + ny * iz);
}

std::vector<std::int32_t> sort_into_cells(CellGrid& grid, const std::vector<Vec3>& x, double cutoff,
                                          const PeriodicZ& pz) {
  const std::size_t n = x.size();
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  if (n > 0) {
    lo = hi = x[0];
    for (const Vec3& p : x) {
      lo.x = std::min(lo.x, p.x); lo.y = std::min(lo.y, p.y); lo.z = std::min(lo.z, p.z);
      hi.x = std::max(hi.x, p.x); hi.y = std::max(hi.y, p.y); hi.z = std::max(hi.z, p.z);
    }
  }
  grid.periodic = pz.on;
  double cell = cutoff;
  // Cap the cell count near the particle count: a stray particle far away must not
  // make the grid explode (the search stays correct with larger cells).
  const double max_cells = 4.0 * static_cast<double>(n) + 64.0;
  // Along a period the cells may be shorter than in x and y (length / nz, at least the
  // cut-off), so enlarging the cells never takes a period that holds 3 below 3.
  const int nz_most = pz.on ? static_cast<int>(pz.length() / cutoff) : 0;
  for (;;) {
    grid.nx = static_cast<int>((hi.x - lo.x) / cell) + 1;
    grid.ny = static_cast<int>((hi.y - lo.y) / cell) + 1;
    grid.nz = pz.on ? std::min(nz_most, std::max(3, static_cast<int>(pz.length() / cell)))
                    : static_cast<int>((hi.z - lo.z) / cell) + 1;
    if (static_cast<double>(grid.nx) * grid.ny * std::max(grid.nz, 1) <= max_cells || (pz.on && grid.nz <= 3)) break;
    cell *= 1.5;
  }
  if (pz.on && grid.nz < 3)
    throw std::invalid_argument("periodic z: period " + std::to_string(pz.length()) +
                                " m is shorter than 3 neighbour cells of " + std::to_string(cutoff) +
                                " m (largest diameter + skin); lengthen the period");
  grid.lo = {lo.x, lo.y, pz.on ? pz.lo : lo.z};
  grid.inv_cx = 1.0 / cell;
  grid.inv_cy = 1.0 / cell;
  grid.inv_cz = pz.on ? grid.nz / pz.length() : 1.0 / cell;

  // Stable counting sort by cell: deterministic, O(N).
  const long nc = grid.cells();
  std::vector<long> cell_of(n);
  grid.cell_start.assign(static_cast<std::size_t>(nc) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = grid.cell_of(x[i]);
    ++grid.cell_start[static_cast<std::size_t>(cell_of[i]) + 1];
  }
  for (long c = 0; c < nc; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
  std::vector<std::int32_t> fill(grid.cell_start.begin(), grid.cell_start.end() - 1);
  std::vector<std::int32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[static_cast<std::size_t>(fill[cell_of[i]]++)] = static_cast<std::int32_t>(i);
  return order;
}

namespace {

// Speed: the particles of the 27 cells around a cell as the runs of indices [b, e) they
// occupy (cells x-1 .. x+1 of one y, z row are contiguous, so are their particles), worked
// out once per cell rather than once per particle (particles are in cell order, so a part's
// rows walk the cells in order). Runs in the order dz, dy, then x ascending.
struct NearRuns {
  int count = 0;
  std::int32_t b[9], e[9];

  NearRuns(const CellGrid& g, long c) {
    const long ix = c % g.nx, iy = (c / g.nx) % g.ny, iz = c / (static_cast<long>(g.nx) * g.ny);
    const long x0 = std::max(ix - 1, 0L), x1 = std::min(ix + 1, static_cast<long>(g.nx) - 1);
    for (long dz = -1; dz <= 1; ++dz) {
      long z = iz + dz;
      if (g.periodic) {
        z = (z + g.nz) % g.nz;
      } else if (z < 0 || z >= g.nz) {
        continue;
      }
      for (long y = std::max(iy - 1, 0L); y <= std::min(iy + 1, static_cast<long>(g.ny) - 1); ++y) {
        const long row = g.nx * (y + g.ny * z);
        b[count] = g.cell_start[static_cast<std::size_t>(row + x0)];
        e[count] = g.cell_start[static_cast<std::size_t>(row + x1 + 1)];
        ++count;
      }
    }
  }
};

}  // namespace

namespace {

// The histories of `carried` (same numbering; a pair in either of its two rows there) into
// the entries of `out` that list the same pairs (in the row of the lower index, or of a
// far-reaching particle's own, build_neighbour_list). Worked
// from the carried contacts (a few per particle), each looked up in the one row of `out`
// that can hold it, not from every entry of `out` searched for in two carried rows: the
// result is the same, a contact listed once in each. Parts write disjoint entries.
void carry_histories(NeighbourList& out, const NeighbourList& carried, ThreadTeam& team) {
  const long rows = static_cast<long>(std::min(carried.rows(), out.rows()));
  if (carried.nbr.empty() || rows == 0) return;
  const int parts = rows >= kMinParallelParticles ? team.size() : 1;
  team.run(parts, [&](int p) {
    for (long a = range_begin(rows, parts, p); a < range_begin(rows, parts, p + 1); ++a)
      for (std::uint32_t e = carried.start[a]; e < carried.start[a + 1]; ++e) {
        const std::int32_t b = carried.nbr[e];
        // The row of the lower index, else (a pair of a far-reaching particle, listed in
        // its own row) the other.
        const std::int32_t lo = std::min(static_cast<std::int32_t>(a), b);
        const std::int32_t hi = std::max(static_cast<std::int32_t>(a), b);
        if (static_cast<std::size_t>(hi) >= out.rows()) continue;
        auto put = [&](std::int32_t row, std::int32_t partner) {
          for (std::uint32_t k = out.start[row]; k < out.start[row + 1]; ++k)
            if (out.nbr[k] == partner) {
              out.hist[k] = carried.hist[e];
              return true;
            }
          return false;
        };
        if (!put(lo, hi)) put(hi, lo);
      }
  });
}

}  // namespace

void build_neighbour_list(NeighbourList& out, const CellGrid& g, const std::vector<Vec3>& x,
                          const std::vector<double>& r, const std::vector<Motion>& motion, double skin,
                          const std::vector<double>& half_skin, const PeriodicZ& pz, const NeighbourList& carried,
                          ThreadTeam& team, ListBuildScratch& scratch) {
  const long n = static_cast<long>(x.size());
  std::vector<std::uint32_t> count(static_cast<std::size_t>(n) + 1, 0);
  // Far-reaching particles: a half-skin above skin/2.
  const double base = 0.5 * skin;
  const bool any_far = std::any_of(half_skin.begin(), half_skin.end(), [&](double h) { return h > base; });
  const auto far = [&](long j) { return any_far && half_skin[static_cast<std::size_t>(j)] > base; };
  double r_most = 0.0, h_most = base;
  if (any_far) {
    for (const double ri : r) r_most = std::max(r_most, ri);
    for (const double h : half_skin) h_most = std::max(h_most, h);
  }
  // Row i lists j > i: a run's particles of lower index are skipped without being read;
  // far-reaching ones list their own pairs.
  auto scan = [&](long i, const NearRuns& near, auto&& emit) {
    const Vec3 xi = x[i];
    const double ri = r[i];
    const bool i_free = motion[i] == Motion::free;
    for (int k = 0; k < near.count; ++k)
      for (std::int32_t j = std::max(near.b[k], static_cast<std::int32_t>(i + 1)); j < near.e[k]; ++j) {
        if ((!i_free && motion[j] != Motion::free) || far(j)) continue;
        Vec3 d = xi - x[j];
        d.z = pz.image(d.z);
        const double cut = ri + r[j] + skin;
        if (norm2(d) < cut * cut) emit(j);
      }
  };
  // Row i of a far-reaching particle (free) in cell c: every partner j within
  // r_i + r_j + h_i + h_j, of lower index too, but the far-reaching ones of lower index
  // (their rows list the pair), from as many cells around as that reach needs.
  auto scan_far = [&](long i, long c, auto&& emit) {
    const Vec3 xi = x[i];
    const double ri = r[i], hi = half_skin[static_cast<std::size_t>(i)];
    const double reach = ri + r_most + hi + h_most;
    const long ix = c % g.nx, iy = (c / g.nx) % g.ny, iz = c / (static_cast<long>(g.nx) * g.ny);
    const long mx = static_cast<long>(std::ceil(reach * g.inv_cx)), my = static_cast<long>(std::ceil(reach * g.inv_cy)),
               mz = static_cast<long>(std::ceil(reach * g.inv_cz));
    const bool all_z = g.periodic && 2 * mz + 1 >= g.nz;  // each z layer once
    const long z0 = all_z ? 0 : iz - mz, z1 = all_z ? g.nz - 1 : iz + mz;
    const long x0 = std::max(ix - mx, 0L), x1 = std::min(ix + mx, static_cast<long>(g.nx) - 1);
    for (long zz = z0; zz <= z1; ++zz) {
      long z = zz;
      if (g.periodic) {
        z = ((z % g.nz) + g.nz) % g.nz;
      } else if (z < 0 || z >= g.nz) {
        continue;
      }
      for (long y = std::max(iy - my, 0L); y <= std::min(iy + my, static_cast<long>(g.ny) - 1); ++y) {
        const long row = g.nx * (y + g.ny * z);
        const std::int32_t b = g.cell_start[static_cast<std::size_t>(row + x0)];
        const std::int32_t e = g.cell_start[static_cast<std::size_t>(row + x1 + 1)];
        for (std::int32_t j = b; j < e; ++j) {
          if (j == i || (j < i && far(j))) continue;
          Vec3 d = xi - x[j];
          d.z = pz.image(d.z);
          const double cut = ri + r[j] + hi + half_skin[static_cast<std::size_t>(j)];
          if (norm2(d) < cut * cut) emit(j);
        }
      }
    }
  };
  // One search per particle: each part lists its rows' partners into a buffer of its own,
  // then the buffers are laid end to end (a count pass first would search twice).
  const int parts = n >= kMinParallelParticles ? team.size() : 1;
  std::vector<std::vector<std::int32_t>>& part_nbr = scratch.part_nbr;
  part_nbr.resize(static_cast<std::size_t>(parts));
  std::vector<long> part_reach(static_cast<std::size_t>(parts), 0);
  team.run(parts, [&](int p) {
    std::vector<std::int32_t>& buf = part_nbr[static_cast<std::size_t>(p)];
    buf.clear();
    const long i0 = range_begin(n, parts, p), i1 = range_begin(n, parts, p + 1);
    if (i0 == i1) return;
    buf.reserve(static_cast<std::size_t>(8 * (i1 - i0)));
    // The cell of row i0: the last cell starting at or before it.
    long c = std::upper_bound(g.cell_start.begin(), g.cell_start.end(), static_cast<std::int32_t>(i0)) -
             g.cell_start.begin() - 1;
    NearRuns near(g, c);
    long reach = 0;
    for (long i = i0; i < i1; ++i) {
      if (g.cell_start[static_cast<std::size_t>(c) + 1] <= i) {
        while (g.cell_start[static_cast<std::size_t>(c) + 1] <= i) ++c;
        near = NearRuns(g, c);
      }
      const std::size_t before = buf.size();
      const auto emit = [&](std::int32_t j) {
        buf.push_back(j);
        if (j - i <= n / 2) reach = std::max(reach, j - i);  // not round a periodic boundary
      };
      if (far(i)) {
        scan_far(i, c, emit);
      } else {
        scan(i, near, emit);
      }
      count[i + 1] = static_cast<std::uint32_t>(buf.size() - before);
    }
    part_reach[static_cast<std::size_t>(p)] = reach;
  });
  for (long i = 0; i < n; ++i) count[i + 1] += count[i];
  out.start = std::move(count);
  out.nbr.resize(out.start[n]);
  out.hist.assign(out.start[n], ContactHistory{});
  team.run(parts, [&](int p) {
    const std::vector<std::int32_t>& buf = part_nbr[static_cast<std::size_t>(p)];
    std::copy(buf.begin(), buf.end(), out.nbr.begin() + out.start[range_begin(n, parts, p)]);
  });
  carry_histories(out, carried, team);
  out.reach = *std::max_element(part_reach.begin(), part_reach.end());
}

}  // namespace centrec::dem
