// The force pass of Simulation (DESIGN.md section 3): Hertz-Mindlin-EPSD2 for every
// pair of the half neighbour list and every candidate wall, gathered deterministically.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "dem/contact_law.hpp"
#include "dem/first_half_step.hpp"
#include "dem/simulation_impl.hpp"

namespace centrec::dem {

// Rows beyond the list's reach at which the force pass fetches partner data ahead.
constexpr long kPrefetchMargin = 256;
// Particles ahead at which the gather pass fetches the parked shares and f, t.
constexpr long kGatherAhead = 16;

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
  ContactHistory* whist = im.wall_hist.data();
  std::uint8_t* touch = im.touch.data();
  Impl::PartnerShare* share = im.share.data();
  const std::uint32_t* rev_pos = im.list.rev_pos.data();
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

  // Pass 1: each pair once, in the row of its lower index. The row owner's share is summed
  // at once; the partner's share is parked for pass 2 at the entry's reverse position.
#pragma omp parallel for schedule(static) num_threads(threads_) if (n >= kMinParallelParticles)
  for (long b = 0; b < nblocks; ++b) {
    BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
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
            share[rev_pos[e]] = Impl::PartnerShare{};
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
        if (i_first) {
          F += res.force;
          T += res.torque_i;
          share[rev_pos[e]] = {-res.force, res.torque_j};
        } else {
          F -= res.force;
          T += res.torque_j;
          share[rev_pos[e]] = {res.force, res.torque_i};
        }
        touch[e] = 1;
        ++tally.pair_contacts;
      }
      if (MOT[i] != Motion::free) {  // carried by the drum: forces on it are not needed
        f_[i] = {};
        t_[i] = {};
        continue;
      }
      std::uint32_t mask = im.wall_mask[i];
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
      f_[i] = F + M[i] * g;
      t_[i] = T;
    }
  }
  // Pass 2: gather the parked partner shares in the fixed reverse-index order, then (see
  // AfterForces) the second half kick and the next step's first half of the same particle.
  const std::uint32_t* rev_start = im.list.rev_start.data();
  const bool kick = after != AfterForces::nothing;
  const bool next = after == AfterForces::second_and_next_first_half;
  FirstHalfStep first;
  if (next) first = begin_first_half();
  const double half = 0.5 * dt;
  const Vec3* XB = im.x_build.data();
  const Vec3 *F_ = f_.data(), *T_ = t_.data();
  const double *IM = inv_m_.data(), *II = inv_inertia_.data();
  // In a film larger than the cache every one of the gather's eleven streams comes from
  // memory, more than the hardware prefetchers keep ahead of: with fetch_ahead (set at the
  // rebuild above a state size, kGatherFetchAheadBytes), particle j + kGatherAhead's shares
  // and data are fetched at j.
  const bool fetch_ahead = im.gather_fetch_ahead;
  // Gather, second half kick and next first half of each particle of block [j0, j_end) in
  // one go (its data are read once); returns the block's largest squared displacement.
  // Entries not in contact hold zeros: adding +0.0 leaves every sum bit for bit as skipping
  // it did, because a sum that starts at +0.0 (F, T and f_, t_ of pass 1) can never be -0.0
  // in round-to-nearest.
  auto sweep_block = [&](long j0, long j_end, BlockTally& tally, auto fetch) {
    double block_d2 = 0.0;
    for (long j = j0; j < j_end; ++j) {
      if constexpr (decltype(fetch)::value) {
        if (const long q = j + kGatherAhead; q < n) {
          const char* group = reinterpret_cast<const char*>(share + rev_start[q]);
          const std::size_t bytes = (rev_start[q + 1] - rev_start[q]) * sizeof(Impl::PartnerShare);
          for (std::size_t off = 0; off < bytes; off += 64) __builtin_prefetch(group + off);
          __builtin_prefetch(F_ + q, 1);
          __builtin_prefetch(T_ + q, 1);
          __builtin_prefetch(V + q, 1);
          __builtin_prefetch(Wv + q, 1);
          __builtin_prefetch(X + q, 1);
          __builtin_prefetch(XB + q);
          __builtin_prefetch(IM + q);
          __builtin_prefetch(II + q);
        }
      }
      if (MOT[j] == Motion::free) {
        Vec3 F = f_[j], T = t_[j];
        for (std::uint32_t k = rev_start[j]; k < rev_start[j + 1]; ++k) {
          F += share[k].force;
          T += share[k].torque;
        }
        f_[j] = F;
        t_[j] = T;
        if ((!is_finite(F) || !is_finite(T) || !is_finite(X[j])) && tally.blowup_index < 0) {
          tally.blowup_index = j;
          tally.blowup_x = X[j];
          tally.blowup_overlap = std::numeric_limits<double>::quiet_NaN();
        }
        if (kick) half_kick(half, inv_m_[j], inv_inertia_[j], F, T, v_[j], w_[j]);  // integrate_second_half
      }
      if (next)
        block_d2 = std::max(block_d2, first.advance(MOT[j], inv_m_[j], inv_inertia_[j], f_[j], t_[j], XB[j], x_[j], v_[j], w_[j]));
    }
    return block_d2;
  };
  double max_d2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads_) if (n >= kMinParallelParticles) reduction(max : max_d2)
  for (long b = 0; b < nblocks; ++b) {
    BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
    const long j0 = b * kBlock, j_end = std::min(n, (b + 1) * kBlock);
    max_d2 = std::max(max_d2, fetch_ahead ? sweep_block(j0, j_end, tally, std::true_type{})
                                          : sweep_block(j0, j_end, tally, std::false_type{}));
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
