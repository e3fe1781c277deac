#pragma once
// Cell grid, spatial sort and half Verlet neighbour lists with contact history
// (docs/dem_physics.md). Pair (i, j), i < j by index, is stored once, in row i, with its
// history (the shares on j are routed by partner_routing.hpp).
// History is kept in the pair's canonical orientation (lower particle id = "i" of the
// contact law), so re-sorting never flips it.
#include <cstdint>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/motion.hpp"
#include "dem/periodic_z.hpp"
#include "dem/thread_team.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

// Below this many particles loops run serially: waking a thread costs more than the work
// (and on a busy machine a whole scheduler slice). Results do not depend on it.
constexpr long kMinParallelParticles = 1024;

struct NeighbourList {
  std::vector<std::uint32_t> start;  // rows + 1 offsets into nbr/hist
  std::vector<std::int32_t> nbr;     // partner index
  std::vector<ContactHistory> hist;  // history of the pair (zero = not in contact)
  // Largest partner distance j - i of an entry that does not reach round a periodic
  // boundary (j - i <= rows / 2): how far ahead of row i its partners' data is first read.
  long reach = 0;
  std::size_t rows() const { return start.empty() ? 0 : start.size() - 1; }
  std::size_t bytes() const;
};

// Entries of `old` with non-zero history, moved to the new numbering, into `out` (not
// `old`; its storage is reused): new row k is old row order[k]; partners are renumbered
// by new_of_old (-1 = removed: entry dropped). Rows of particles added after `old` was
// built (order[k] >= old.rows()) are empty.
void carry_contacts(const NeighbourList& old, const std::vector<std::int32_t>& order,
                    const std::vector<std::int32_t>& new_of_old, NeighbourList& out);

// Uniform cell grid with cells no smaller than the interaction cut-off.
struct CellGrid {
  Vec3 lo;
  double inv_cx = 0, inv_cy = 0, inv_cz = 0;
  int nx = 1, ny = 1, nz = 1;
  bool periodic = false;
  std::vector<std::int32_t> cell_start;  // ncells + 1, valid after particles are in cell order

  long cell_of(Vec3 x) const;
  long cells() const { return static_cast<long>(nx) * ny * nz; }
};

// Sizes the grid to the particles' bounding box (z: the period when periodic) and returns
// the stable cell order: order[k] = index of the particle that goes to position k. Also
// fills grid.cell_start for the particles once they are in that order. Throws
// std::invalid_argument if a period holds fewer than 3 cells.
std::vector<std::int32_t> sort_into_cells(CellGrid& grid, const std::vector<Vec3>& x, double cutoff,
                                          const PeriodicZ& pz);

// Speed: build_neighbour_list's per-thread buffers, kept from one build to the next so a
// build does not fault in fresh pages.
struct ListBuildScratch {
  std::vector<std::vector<std::int32_t>> part_nbr;
};

// Half list of particles already in cell order: row i holds j > i with
// |x_i - x_j| < r_i + r_j + skin, unless neither is Motion::free (nothing to compute).
// Far-reaching particles (half_skin[i] > skin/2; half_skin empty: none) list their own
// pairs, partners of lower index too: j with |x_i - x_j| < r_i + r_j + half_skin[i] +
// half_skin[j] (a pair of two of them in the row of the lower index), and no other row
// names them. Histories are taken from `carried` (same numbering; a pair may sit in either
// of its two rows there), others start at zero.
void build_neighbour_list(NeighbourList& out, const CellGrid& grid, const std::vector<Vec3>& x,
                          const std::vector<double>& r, const std::vector<Motion>& motion, double skin,
                          const std::vector<double>& half_skin, const PeriodicZ& pz, const NeighbourList& carried,
                          ThreadTeam& team, ListBuildScratch& scratch);

}  // namespace centrec::dem
