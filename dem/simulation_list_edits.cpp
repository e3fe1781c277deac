// Speed: particles added or removed between steps join or leave a valid neighbour list
// without a rebuild (docs/dem_physics.md "Neighbour lists"). A fed drum inserts a few
// particles at the inlet and removes a few past the outlet every feeder batch (~50 steps);
// a full rebuild (spatial sort, a 27-cell search for every particle, share routing) each
// time cost the drum more than its force pass's share of the walls (docs/benchmarks.md).
//
// Insertion: the new particles are appended (the arrays' last rows) and each gets a row
// holding every partner within reach, old ones (lower index: "reverse" entries) and new
// ones of higher index. A particle named by a row after its own has its shares parked
// (partner_routing.hpp): it is totalled and integrated in the parked pass, after every row,
// so the sums keep a fixed order and no row reads a particle already moved. Reach: a pair
// must be listed if it can touch before the next rebuild. The new particle gets its
// half-skin h_p as at a build; the next rebuild comes before the pair's displacements (the
// new one's from where it was inserted, the old one's from where it was at the last build)
// add up to more than h_p + h_j (ListSlack), and the old one may already be up to 2 h_j
// from there and come back past it: r_p + r_j + h_p + 3 h_j (2 skin for two of skin/2).
//
// Removal: the arrays are compacted in order, the list's rows and entries with them, in
// place (entries naming a removed particle dropped). Compaction keeps every row's partners on the
// same side of it, so the list stays a valid half list.
//
// The next rebuild (two particles moved a skin between them, or rebuild_lists) makes the list from scratch;
// histories carry over as at any rebuild. Results differ from a rebuild at every insertion
// only by the order of the sums, and are the same for any thread count.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "dem/first_half_step.hpp"
#include "dem/simulation_impl.hpp"

namespace centrec::dem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void Simulation::take_in_new_particles() {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& im = *impl_;
  NeighbourList& list = im.list;
  const std::size_t n0 = list.rows(), n = x_.size();
  // Half-skins of the new particles (those of the old ones were set at the build).
  im.half_skin.resize(n);
  for (std::size_t p = n0; p < n; ++p) im.half_skin[p] = half_skin_of(p);
  double h_most = 0.0, h_new = 0.0;
  for (std::size_t i = 0; i < n; ++i) h_most = std::max(h_most, im.half_skin[i]);
  for (std::size_t p = n0; p < n; ++p) h_new = std::max(h_new, im.half_skin[p]);

  // Candidates: every particle inside the new ones' bounding box widened by the reach.
  double r_new = 0.0, r_all = 0.0;
  for (std::size_t i = 0; i < n; ++i) r_all = std::max(r_all, r_[i]);
  Vec3 lo = x_[n0], hi = x_[n0];
  for (std::size_t p = n0; p < n; ++p) {
    r_new = std::max(r_new, r_[p]);
    lo = {std::min(lo.x, x_[p].x), std::min(lo.y, x_[p].y), std::min(lo.z, x_[p].z)};
    hi = {std::max(hi.x, x_[p].x), std::max(hi.y, x_[p].y), std::max(hi.z, x_[p].z)};
  }
  const double pad = r_new + r_all + h_new + 3.0 * h_most;
  const bool whole_period_z = im.pz.on && hi.z - lo.z + 2.0 * pad >= im.pz.length();
  std::vector<std::int32_t> near;
  for (std::size_t j = 0; j < n; ++j) {
    const Vec3 q = x_[j];
    if (q.x < lo.x - pad || q.x > hi.x + pad || q.y < lo.y - pad || q.y > hi.y + pad) continue;
    if (!im.pz.on) {
      if (q.z < lo.z - pad || q.z > hi.z + pad) continue;
    } else if (!whole_period_z) {
      const double mid = 0.5 * (lo.z + hi.z);
      if (std::fabs(im.pz.image(q.z - mid)) > 0.5 * (hi.z - lo.z) + pad) continue;
    }
    near.push_back(static_cast<std::int32_t>(j));
  }

  // Rows n0 .. n-1: old partners (reverse entries) and new partners of higher index.
  for (std::size_t p = n0; p < n; ++p) {
    const bool p_free = motion_[p] == Motion::free;
    for (const std::int32_t j : near) {
      const std::size_t uj = static_cast<std::size_t>(j);
      if (uj == p || (uj >= n0 && uj < p)) continue;  // itself; a new partner listed in its own row
      if (!p_free && motion_[uj] != Motion::free) continue;
      Vec3 d = x_[p] - x_[uj];
      d.z = im.pz.image(d.z);
      const double cut = r_[p] + r_[uj] + im.half_skin[p] + 3.0 * im.half_skin[uj];
      if (norm2(d) >= cut * cut) continue;
      list.nbr.push_back(j);
      list.hist.push_back(ContactHistory{});
      im.touch.push_back(0);
      if (uj > p) list.reach = std::max(list.reach, static_cast<long>(uj - p));
    }
    list.start.push_back(static_cast<std::uint32_t>(list.nbr.size()));
  }

  // Where the new particles are, as seen at the last build (the displacement check
  // measures from there, in the drum frame when the lists follow the drum).
  const DrumMotion& drum = cfg_.drum;
  const double c = std::cos(im.angle_since_build), s = std::sin(im.angle_since_build);
  im.x_build.resize(n);
  im.wall_mask.resize(n);
  for (std::size_t p = n0; p < n; ++p) {
    im.x_build[p] = drum.origin + rotate(x_[p] - drum.origin, drum.axis, c, -s);
    im.wall_mask[p] = candidate_walls(p);
  }
  im.acc_f.resize(n, Vec3{});
  im.acc_t.resize(n, Vec3{});
  im.routing = PartnerRouting{};  // planned again by the next force pass
  im.share.clear();
  ++im.list_edits;
  times_.list_edit += seconds_since(t0);
}

void Simulation::remove_from_lists(const std::vector<std::int32_t>& order, const std::vector<std::int32_t>& new_of_old) {
  if (impl_->list.rows() < x_.size()) take_in_new_particles();
  const auto t0 = std::chrono::steady_clock::now();
  Impl& im = *impl_;
  // Compacted in place: `order` is ascending, so an entry only moves towards the front, and
  // the arrays keep their capacity (a fresh copy of the list, ~25 MB on the fed drum, cost
  // page faults here and a reallocation at the next insertion's first append).
  NeighbourList& list = im.list;
  const std::vector<std::uint32_t> old_start = list.start;
  std::size_t w = 0;
  list.start.resize(order.size() + 1);
  list.start[0] = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t row = static_cast<std::size_t>(order[k]);
    for (std::uint32_t e = old_start[row]; e < old_start[row + 1]; ++e) {
      const std::int32_t j = new_of_old[static_cast<std::size_t>(list.nbr[e])];
      if (j < 0) continue;
      list.nbr[w] = j;
      list.hist[w] = list.hist[e];
      im.touch[w] = im.touch[e];
      ++w;
    }
    list.start[k + 1] = static_cast<std::uint32_t>(w);
  }
  list.nbr.resize(w);
  list.hist.resize(w);
  im.touch.resize(w);
  // list.reach is kept: compaction only shortens a row's reach (a prefetch distance).
  permute_particles(order);
  permute_rows(im.x_build, order);
  permute_rows(im.wall_mask, order);
  permute_rows(im.half_skin, order);
  im.acc_f.assign(order.size(), Vec3{});
  im.acc_t.assign(order.size(), Vec3{});
  im.routing = PartnerRouting{};
  im.share.clear();
  ++im.list_edits;
  times_.list_edit += seconds_since(t0);
}

}  // namespace centrec::dem
