// The force pass of Simulation (docs/dem_physics.md): Hertz-Mindlin-EPSD2 for every
// pair of the half neighbour list and every candidate wall, summed deterministically.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "dem/contact_law.hpp"
#include "dem/first_half_step.hpp"
#include "dem/simulation_impl.hpp"

namespace centrec::dem {

// Rows beyond the list's reach at which the force pass fetches partner data ahead.
constexpr long kPrefetchMargin = 256;
// Rows ahead at which the pass fetches the row's own streams (list entries, histories,
// wall data, f, t and integration data; its accumulators come with the partner data): at ~100-150 ns per row, 32 rows are well over a memory
// latency ahead, and the few kB in flight stay inside L1 + L2.
constexpr long kRowFetchAhead = 32;

namespace {

// What follows a particle's completed force and torque (see Simulation::AfterForces): the
// blow-up check, the second half kick, the next step's first half. Returns the squared
// displacement since the last build (0 without the first half).
struct ParticleFinish {
  bool kick = false, next = false;
  double half = 0.0;
  FirstHalfStep first;
  const Motion* mot = nullptr;
  const double *inv_m = nullptr, *inv_inertia = nullptr;
  const Vec3* x_build = nullptr;
  Vec3 *x = nullptr, *v = nullptr, *w = nullptr;

  double operator()(long i, Vec3 f, Vec3 t, BlockTally& tally) const {
    if (mot[i] == Motion::free) {
      if ((!is_finite(f) || !is_finite(t) || !is_finite(x[i])) && tally.blowup_index < 0) {
        tally.blowup_index = i;
        tally.blowup_x = x[i];
        tally.blowup_overlap = std::numeric_limits<double>::quiet_NaN();
      }
      if (kick) half_kick(half, inv_m[i], inv_inertia[i], f, t, v[i], w[i]);  // integrate_second_half
    }
    return next ? first.advance(mot[i], inv_m[i], inv_inertia[i], f, t, x_build[i], x[i], v[i], w[i]) : 0.0;
  }
};

}  // namespace

double Simulation::compute_forces(bool update_history, AfterForces after) {
  Impl& im = *impl_;
  const long n = static_cast<long>(x_.size());
  const long nblocks = (n + kBlock - 1) / kBlock;
  const std::size_t nw = walls_.size();
  if (im.tallies.size() < static_cast<std::size_t>(nblocks)) im.tallies.resize(static_cast<std::size_t>(nblocks));
  const double dt = dt_;
  const double limit = blowup_fraction_;
  const bool relative_rolling = cfg_.wall_rolling == WallRolling::relative;
  const PeriodicZ pz = im.pz;
  const Vec3 g = cfg_.gravity;
  const std::uint32_t* start = im.list.start.data();
  const std::int32_t* nbr = im.list.nbr.data();
  ContactHistory* hist = im.list.hist.data();
  ContactHistory* whist = wall_hist_.data();
  std::uint8_t* touch = im.touch.data();
  const std::uint32_t* wall_mask = im.wall_mask.data();
  // Row ranges of the pair pass: one per thread (results do not depend on their number).
  const long parts = n >= kMinParallelParticles ? std::max(1, threads_) : 1;
  if (im.routing.parts != parts) {
    im.routing = route_partner_shares(im.list, kBlock, parts);
    im.share.assign(im.routing.parked(), Impl::PartnerShare{});
  }
  Impl::PartnerShare* share = im.share.data();
  const std::uint32_t* slot = im.routing.slot.data();
  Vec3 *ACC_F = im.acc_f.data(), *ACC_T = im.acc_t.data();
  const Vec3 *X = x_.data(), *V = v_.data(), *Wv = w_.data();
  const double *R = r_.data(), *M = m_.data();
  const std::int64_t* ID = id_.data();
  const int* MAT = mat_.data();
  const Motion* MOT = motion_.data();
  // Partners' data are first read about list.reach rows ahead of the row being worked on,
  // in cell runs that jump from one ring arc and cell row to the next, which the hardware
  // prefetchers do not follow: a film larger than the cache then waits on memory at every
  // first read. Fetching particle i + ahead at row i turns those reads into cache hits.
  const long ahead = im.list.reach + kPrefetchMargin;

  ParticleFinish finish;
  finish.kick = after != AfterForces::nothing;
  finish.next = after == AfterForces::second_and_next_first_half;
  finish.half = 0.5 * dt;
  if (finish.next) finish.first = begin_first_half();
  finish.mot = MOT;
  finish.inv_m = inv_m_.data();
  finish.inv_inertia = inv_inertia_.data();
  finish.x_build = im.x_build.data();
  finish.x = x_.data();
  finish.v = v_.data();
  finish.w = w_.data();
  const std::uint32_t* park_start = im.routing.park_start.data();

  // Pass 1: each pair once, in the row of its lower index. The row owner's share is summed
  // at once; the partner's share is added to its accumulator or parked (im.routing). Rows
  // name only partners of higher index, so at the end of its row a particle with direct
  // shares only has its whole force and no later row reads it: it is finished there, while
  // its data are in cache (one sweep over the particle arrays per step).
  double max_d2 = 0.0;
#pragma omp parallel for schedule(static, 1) num_threads(threads_) if (parts > 1) reduction(max : max_d2)
  for (long part = 0; part < parts; ++part)
  for (long b = first_block_of_part(nblocks, parts, part); b < first_block_of_part(nblocks, parts, part + 1); ++b) {
    BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
    double block_d2 = 0.0;
    tally.wall_force.assign(nw, Vec3{});
    tally.pair_contacts = tally.wall_contacts = 0;
    tally.blowup_index = -1;
    const long i_end = std::min(n, (b + 1) * kBlock);
    for (long i = b * kBlock; i < i_end; ++i) {
      if (const long p = i + ahead; p < n) {
        __builtin_prefetch(X + p);
        __builtin_prefetch(R + p);
        __builtin_prefetch(ID + p);
        __builtin_prefetch(MAT + p);
        __builtin_prefetch(M + p);
        __builtin_prefetch(V + p);
        __builtin_prefetch(Wv + p);
        __builtin_prefetch(ACC_F + p, 1);  // first written by the row that first names p
        __builtin_prefetch(ACC_T + p, 1);
      }
      // The row's own streams: about twenty arrays walked at different paces (57 bytes per
      // list entry, 1 to 24 bytes per particle), more than the hardware prefetchers track,
      // so a film beyond the cache waited on the next line of one stream after another.
      if (const long q = i + kRowFetchAhead; q < n) {
        // Fixed counts, no loops: a row holds ~5 entries, whose histories span up to five
        // lines from the line of its first; the next rows' fetches cover longer rows.
        const std::uint32_t e0 = start[q];
        // (Addresses as integers: past the list's end they are fetched, never dereferenced.)
        const std::uintptr_t h = reinterpret_cast<std::uintptr_t>(hist + e0);
        for (std::uintptr_t line = 0; line < 5; ++line)
          __builtin_prefetch(reinterpret_cast<const void*>(h + 64 * line), 1);
        __builtin_prefetch(nbr + e0);
        __builtin_prefetch(slot + e0);
        __builtin_prefetch(touch + e0, 1);
        __builtin_prefetch(start + q + 1);
        __builtin_prefetch(park_start + q + 1);
        __builtin_prefetch(MOT + q);
        __builtin_prefetch(wall_mask + q);
        __builtin_prefetch(whist + static_cast<std::size_t>(q) * nw, 1);
        __builtin_prefetch(f_.data() + q, 1);
        __builtin_prefetch(t_.data() + q, 1);
        __builtin_prefetch(finish.x_build + q);
        __builtin_prefetch(finish.inv_m + q);
        __builtin_prefetch(finish.inv_inertia + q);
      }
      const Vec3 xi = X[i];
      const double ri = R[i];
      const std::int64_t idi = ID[i];
      Vec3 F{}, T{};
      for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) {
        const std::int32_t j = nbr[e];
        Vec3 d = xi - X[j];
        d.z = pz.image(d.z);
        const double rsum = ri + R[j];
        const double dist2 = norm2(d);
        if (dist2 >= rsum * rsum) {
          if (touch[e]) {  // just separated: forget the pair (reads 1 byte, not the history)
            touch[e] = 0;
            hist[e] = ContactHistory{};
            if (slot[e] != PartnerRouting::kDirect) share[slot[e]] = Impl::PartnerShare{};
          }
          continue;
        }
        const double dist = std::sqrt(dist2);
        const double delta = rsum - dist;
        if (!(delta <= limit * std::min(ri, R[j])) && tally.blowup_index < 0) {
          tally.blowup_index = i;
          tally.blowup_x = xi;
          tally.blowup_overlap = delta;
          tally.blowup_partner = "particle id " + std::to_string(ID[j]);
        }
        // Canonical operand order (lower id first): the result and the stored history do
        // not depend on which of the two is the row owner after a re-sort.
        const bool i_first = idi < ID[j];
        const long a = i_first ? i : j, c = i_first ? j : i;
        const double ra = R[a], rc = R[c], ma = M[a], mc = M[c];
        const Vec3 nrm = (1.0 / dist) * (i_first ? d : -d);
        const double arm_a = ra - 0.5 * delta, arm_c = rc - 0.5 * delta;
        const ContactInput in{delta,
                              nrm,
                              contact_velocity(V[a] - V[c], Wv[a], Wv[c], arm_a, arm_c, nrm),
                              Wv[a] - Wv[c],
                              ra * rc / (ra + rc),
                              ma * mc / (ma + mc),
                              arm_a,
                              arm_c};
        const ContactResult res = evaluate_contact(pair(MAT[a], MAT[c]), in, hist[e], dt);
        if (update_history) hist[e] = res.history;
        Vec3 fj, tj;
        if (i_first) {
          F += res.force;
          T += res.torque_i;
          fj = -res.force;
          tj = res.torque_j;
        } else {
          F -= res.force;
          T += res.torque_j;
          fj = res.force;
          tj = res.torque_i;
        }
        if (const std::uint32_t s = slot[e]; s == PartnerRouting::kDirect) {
          ACC_F[j] += fj;
          ACC_T[j] += tj;
        } else {
          share[s] = {fj, tj};
        }
        touch[e] = 1;
        ++tally.pair_contacts;
      }
      // The partners' direct shares, summed in row order, come first (partner_routing.hpp).
      const Vec3 acc_f = ACC_F[i], acc_t = ACC_T[i];
      ACC_F[i] = {};
      ACC_T[i] = {};
      const bool direct = park_start[i] == park_start[i + 1];
      if (MOT[i] != Motion::free) {  // carried by the drum: forces on it are not needed
        f_[i] = {};
        t_[i] = {};
        if (direct) block_d2 = std::max(block_d2, finish(i, Vec3{}, Vec3{}, tally));
        continue;
      }
      std::uint32_t mask = wall_mask[i];
      while (mask != 0u) {
        const int wi = __builtin_ctz(mask);
        mask &= mask - 1u;
        const Wall& wall = walls_[static_cast<std::size_t>(wi)];
        ContactHistory& h = whist[static_cast<std::size_t>(i) * nw + static_cast<std::size_t>(wi)];
        double dist;
        Vec3 nrm, point;
        if (!wall_geometry(wall, xi, dist, nrm, point) || dist >= ri) {
          h = ContactHistory{};
          continue;
        }
        const double delta = ri - dist;
        if (!(delta <= limit * ri) && tally.blowup_index < 0) {
          tally.blowup_index = i;
          tally.blowup_x = xi;
          tally.blowup_overlap = delta;
          tally.blowup_partner = "wall " + std::to_string(wi);
        }
        const double arm = ri - 0.5 * delta;
        const ContactInput in{delta,
                              nrm,
                              contact_velocity(V[i] - wall_velocity_at(wall, point), Wv[i], Vec3{}, arm, 0.0, nrm),
                              relative_rolling ? Wv[i] - wall.angular_velocity : Wv[i],
                              ri,
                              M[i],
                              arm,
                              0.0};
        const ContactResult res = evaluate_contact(pair(MAT[i], wall.material), in, h, dt);
        if (update_history) h = res.history;
        F += res.force;
        T += res.torque_i;
        tally.wall_force[static_cast<std::size_t>(wi)] -= res.force;
        ++tally.wall_contacts;
      }
      const Vec3 f = acc_f + (F + M[i] * g), t = acc_t + T;
      f_[i] = f;
      t_[i] = t;
      if (direct) block_d2 = std::max(block_d2, finish(i, f, t, tally));
    }
    max_d2 = std::max(max_d2, block_d2);
  }
  // Pass 2: the parked particles, once every range is done: their shares summed in row
  // order, then their own part, as the direct ones (partner_routing.hpp); then finished.
  // Parked slots not in contact hold zeros: adding +0.0 leaves a sum bit for bit as
  // skipping it does (the direct sums skip them), because a sum that starts at +0.0 can
  // never be -0.0 in round-to-nearest; for the same reason a parked particle's own part,
  // +0.0 + (F + m g) in pass 1, adds as the direct one's F + m g does.
  if (im.routing.parked() > 0) {
#pragma omp parallel for schedule(static) num_threads(threads_) if (parts > 1) reduction(max : max_d2)
    for (long b = 0; b < nblocks; ++b) {
      BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
      const long j_end = std::min(n, (b + 1) * kBlock);
      for (long j = b * kBlock; j < j_end; ++j) {
        if (park_start[j] == park_start[j + 1]) continue;
        if (MOT[j] == Motion::free) {
          Vec3 sf{}, st{};
          for (std::uint32_t k = park_start[j]; k < park_start[j + 1]; ++k) {
            sf += share[k].force;
            st += share[k].torque;
          }
          f_[j] = sf + f_[j];
          t_[j] = st + t_[j];
        }
        max_d2 = std::max(max_d2, finish(j, f_[j], t_[j], tally));
      }
    }
  }
  // Fixed-order reduction over blocks.
  for (auto& f : wall_force_) f = {};
  im.pair_contacts = im.wall_contacts = 0;
  for (long b = 0; b < nblocks; ++b) {
    const BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
    if (tally.blowup_index >= 0)
      report_blow_up(static_cast<std::size_t>(tally.blowup_index), tally.blowup_x, tally.blowup_overlap,
                     tally.blowup_partner);
    for (std::size_t w = 0; w < nw; ++w) wall_force_[w] += tally.wall_force[w];
    im.pair_contacts += tally.pair_contacts;
    im.wall_contacts += tally.wall_contacts;
  }
  return max_d2;
}

}  // namespace centrec::dem
