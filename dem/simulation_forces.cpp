// The force pass of Simulation (docs/dem_physics.md): Hertz-Mindlin-EPSD2 for every
// pair of the half neighbour list and every candidate wall, summed deterministically
// (docs/architecture.md "Threads and determinism"). compute_forces works on ranges of
// rows (one per thread), one row (particle i) at a time (ForcePass::sweep_rows; with AVX2
// the contact law of four pairs at once, results applied in the same order):
//   1. ForcePass::fetch_ahead   the data the rows ahead will read, into cache
//   2. ForcePass::pair_row      the contacts of i with its partners j > i: the owner's
//                               share summed at once, the partner's routed (route_share)
//   3. ForcePass::row_total     i's direct partner shares, its wall contacts
//                               (wall_contacts) and gravity; then i is integrated
//                               (ParticleFinish) unless a share of it is parked
// then, once every range is done:
//   4. ForcePass::parked_total  each parked particle: its shares summed, then integrated
//   5. the per-block tallies (wall forces, counts, blow-ups) reduced in block order.
// Each step's arithmetic is written once, in a fixed operation order: results are the
// same bits for any thread count.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/first_half_step.hpp"
#include "dem/pair_batch_avx2.hpp"
#include "dem/simulation_impl.hpp"

// The pass's steps are inlined into its loops: no call per row or per list entry.
#define CENTREC_INLINE [[gnu::always_inline]] inline

namespace centrec::dem {

// Rows beyond the list's reach at which the force pass fetches partner data ahead.
constexpr long kPrefetchMargin = 256;
// Rows ahead at which the pass fetches the row's own streams (list entries, histories,
// wall data, f, t and integration data; its accumulators come with the partner data): at
// ~100-150 ns per row, 32 rows are well over a memory latency ahead, and the few kB in
// flight stay inside L1 + L2.
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

  CENTREC_INLINE double operator()(long i, Vec3 f, Vec3 t, BlockTally& tally) const {
    if (mot[i] == Motion::free) {
      if (!is_finite(f) || !is_finite(t) || !is_finite(x[i]))
        tally.note_blow_up(i, x[i], std::numeric_limits<double>::quiet_NaN(), [] { return std::string(); });
      if (kick) half_kick(half, inv_m[i], inv_inertia[i], f, t, v[i], w[i]);  // integrate_second_half
    }
    return next ? first.advance(mot[i], inv_m[i], inv_inertia[i], f, t, x_build[i], x[i], v[i], w[i]) : 0.0;
  }
};

// The arrays and constants of one force pass, as plain pointers (the loops index them
// directly), and its steps for one row.
struct ForcePass {
  // Particles.
  const Vec3 *X, *V, *Wv;
  const double *R, *M;
  const std::int64_t* ID;
  const int* MAT;
  const Motion* MOT;
  Vec3 *F_out, *T_out;  // f_, t_: the completed force and torque
  // Neighbour list and its per-entry state.
  const std::uint32_t* start;
  const std::int32_t* nbr;
  ContactHistory* hist;
  std::uint8_t* touch;  // entry in contact at the last pass (then hist may be non-zero)
  // Partner routing (partner_routing.hpp).
  const std::uint32_t* slot;
  const std::uint32_t* park_start;
  PartnerShare* share;
  Vec3 *ACC_F, *ACC_T;  // direct shares, zero outside the pair pass
  // Walls.
  const Wall* walls;
  std::size_t nw;
  ContactHistory* whist;  // particles x walls
  const std::uint32_t* wall_mask;
  const double* H;  // half-skins (ListSlack), set at each rebuild
  // Pair constants (materials x materials) and the step's constants.
  const PairConstants* pc;
  std::size_t n_mat;
  PeriodicZ pz;
  Vec3 g;
  double dt, limit;
  bool relative_rolling, update_history, batched;
  long n, ahead;
  ParticleFinish finish;

  const PairConstants& pair(int a, int b) const { return pc[static_cast<std::size_t>(a) * n_mat + b]; }

  // 1. Speed: data fetched into cache before the rows read them. Partners' data are first
  // read about list.reach rows ahead of the row being worked on, in cell runs that jump
  // from one ring arc and cell row to the next, which the hardware prefetchers do not
  // follow: a film larger than the cache then waits on memory at every first read.
  // Fetching particle i + ahead at row i turns those reads into cache hits. The row's own
  // streams are about twenty arrays walked at different paces (57 bytes per list entry,
  // 1 to 24 bytes per particle), more than the hardware prefetchers track, so row
  // i + kRowFetchAhead's lines of each are fetched too.
  CENTREC_INLINE void fetch_ahead(long i) const {
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
      __builtin_prefetch(H + q);
      __builtin_prefetch(whist + static_cast<std::size_t>(q) * nw, 1);
      __builtin_prefetch(F_out + q, 1);
      __builtin_prefetch(T_out + q, 1);
      __builtin_prefetch(finish.x_build + q);
      __builtin_prefetch(finish.inv_m + q);
      __builtin_prefetch(finish.inv_inertia + q);
    }
  }

  // 2. The pairs of row i (partners j > i): the owner's share summed into F, T; the
  // partner's share routed. Each pair in canonical operand order (lower id first): the
  // result and the stored history do not depend on which of the two owns the row after a
  // re-sort. walk_row tests each entry for contact (forgetting separated ones) and hands
  // the contacts on in entry order; apply_pair uses a contact's result.
  CENTREC_INLINE void pair_row(long i, Vec3& F, Vec3& T, BlockTally& tally) const {
    walk_row(i, [&](std::uint32_t e, std::int32_t j, bool i_first, long a, long c, Vec3 sd, double dist2,
                    double rsum) {
      const double dist = std::sqrt(dist2);
      const double delta = rsum - dist;
      const ContactInput in = pair_contact_input(sd, dist, delta, R[a], R[c], M[a], M[c], V[a], V[c], Wv[a], Wv[c]);
      const ContactResult res = evaluate_contact(pair(MAT[a], MAT[c]), in, hist[e], dt);
      apply_pair(i, e, j, i_first, delta, res.force, res.torque_i, res.torque_j, res.history, F, T, tally);
    });
  }

  // Steps 1-3 for rows i0 .. i1-1 (one block). Returns the rows' slack (ListSlack).
  CENTREC_INLINE ListSlack sweep_rows(long i0, long i1, BlockTally& tally) const {
#ifdef CENTREC_PAIR_BATCH
    if (batched) return sweep_rows_batched(i0, i1, tally);
#endif
    return sweep_rows_scalar(i0, i1, tally);
  }

  CENTREC_INLINE ListSlack sweep_rows_scalar(long i0, long i1, BlockTally& tally) const {
    ListSlack d2;
    for (long i = i0; i < i1; ++i) {
      fetch_ahead(i);
      Vec3 F{}, T{};
      pair_row(i, F, T, tally);
      d2.add(row_total(i, F, T, tally), H[i]);
    }
    return d2;
  }
#ifdef CENTREC_PAIR_BATCH
  // Speed: steps 1-3 for rows i0 .. i1-1 (one block) with the contact law evaluated four
  // pairs at a time in AVX2 lanes (pair_batch_avx2.hpp), the lanes filled across row ends.
  // The contacts are collected in entry order (walk_row), evaluated when four are (and at
  // the block's end, spare lanes repeating one), then applied in that order (apply_pair);
  // a row is totalled (row_total) once the contacts of every row up to it are applied.
  // Every sum, history, share and tally entry is thus made in the scalar order, pair_row
  // then row_total row by row: the same bits. Pending rows read only particles above the
  // rows totalled meanwhile, which their totals do not move.
  CENTREC_INLINE ListSlack sweep_rows_batched(long i0, long i1, BlockTally& tally) const {
    pair_batch::PairRef batch[pair_batch::kLanes];
    struct Entry {
      long i;
      std::uint32_t e;
      std::int32_t j;
      bool i_first;
    } entry[pair_batch::kLanes];
    int count = 0;
    ListSlack d2;
    long next_total = i0, open = -1;  // the first row not totalled; the row whose sums F, T are open
    Vec3 F{}, T{};
    const auto total_until = [&](long end) {  // rows next_total .. end-1: all their contacts applied
      for (; next_total < end; ++next_total) {
        if (next_total != open) {
          d2.add(row_total(next_total, Vec3{}, Vec3{}, tally), H[next_total]);
          continue;
        }
        d2.add(row_total(next_total, F, T, tally), H[next_total]);
        F = T = Vec3{};
        open = -1;
      }
    };
    const auto evaluate_batch = [&] {
      for (int k = 0; k < count; ++k) {  // the canonical operand order of each contact (walk_row)
        Entry& en = entry[k];
        pair_batch::PairRef& b = batch[k];
        en.i_first = ID[en.i] < ID[en.j];
        b.a = en.i_first ? en.i : en.j;
        b.c = en.i_first ? en.j : en.i;
        if (!en.i_first) b.sd = -b.sd;
        b.pc = &pair(MAT[b.a], MAT[b.c]);
      }
      pair_batch::PairResults r;
      pair_batch::evaluate_pairs(batch, count, {V, Wv, R, M}, dt, r);
      for (int k = 0; k < count; ++k) {
        const Entry& en = entry[k];
        if (en.i != open) {
          total_until(en.i);
          open = en.i;
        }
        apply_pair(en.i, en.e, en.j, en.i_first, r.delta[k], r.force[k], r.torque_a[k], r.torque_c[k],
                   ContactHistory{r.shear[k], r.roll[k]}, F, T, tally);
      }
      count = 0;
    };
    // walk_row's test, written without a branch on its outcome (speed: in a film about a
    // third of the entries are contacts, in no order the processor can predict): every
    // entry is written to the next free lane, which only a contact keeps. The contacts,
    // their order and their arithmetic are walk_row's; the operand order is set in
    // evaluate_batch, for the contacts only.
    for (long i = i0; i < i1; ++i) {
      fetch_ahead(i);
      const Vec3 xi = X[i];
      const double ri = R[i];
      for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) {
        const std::int32_t j = nbr[e];
        Vec3 d;
        double rsum;
        const double dist2 = separation(xi, ri, j, d, rsum);
        const bool apart = dist2 >= rsum * rsum;  // false for NaN: a non-finite pair goes to the law's checks
        if (apart & (touch[e] != 0)) forget(e);
        batch[count].sd = d;
        batch[count].dist2 = dist2;
        batch[count].rsum = rsum;
        batch[count].old = &hist[e];
        entry[count].i = i;
        entry[count].e = e;
        entry[count].j = j;
        count += apart ? 0 : 1;
        if (count == pair_batch::kLanes) evaluate_batch();
      }
      if (count == 0) total_until(i + 1);
    }
    if (count > 0) evaluate_batch();
    total_until(i1);
    return d2;
  }
#endif

  // The separation of a row's particle (at xi, radius ri) from partner j: d = xi - x_j
  // (minimum image) into d, r_i + r_j into rsum; returns |d|^2.
  CENTREC_INLINE double separation(Vec3 xi, double ri, std::int32_t j, Vec3& d, double& rsum) const {
    d = xi - X[j];
    d.z = pz.image(d.z);
    rsum = ri + R[j];
    return norm2(d);
  }

  // The entries of row i in order: a separated pair is forgotten; for one in contact,
  // contact(e, j, i_first, a, c, sd, dist2, rsum) with a, c the pair in canonical order,
  // sd = x_a - x_c (minimum image), dist2 = |sd|^2 < rsum^2, rsum = R_i + R_j.
  template <class Contact>
  CENTREC_INLINE void walk_row(long i, Contact contact) const {
    const Vec3 xi = X[i];
    const double ri = R[i];
    const std::int64_t idi = ID[i];
    for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) {
      const std::int32_t j = nbr[e];
      Vec3 d;
      double rsum;
      const double dist2 = separation(xi, ri, j, d, rsum);
      if (dist2 >= rsum * rsum) {
        if (touch[e]) forget(e);
        continue;
      }
      const bool i_first = idi < ID[j];
      contact(e, j, i_first, i_first ? i : j, i_first ? j : i, i_first ? d : -d, dist2, rsum);
    }
  }

  // The result of entry e's contact (i with j, overlap delta; force and torques of the
  // pair in canonical order, a the lower id), in entry order: the overlap checked, the
  // history stored, the owner's share summed into F, T, the partner's routed.
  CENTREC_INLINE void apply_pair(long i, std::uint32_t e, long j, bool i_first, double delta, Vec3 force,
                                 Vec3 torque_a, Vec3 torque_c, const ContactHistory& history, Vec3& F, Vec3& T,
                                 BlockTally& tally) const {
    if (!(delta <= limit * std::min(R[i], R[j])))
      tally.note_blow_up(i, X[i], delta, [&] { return "particle id " + std::to_string(ID[j]); });
    if (update_history) hist[e] = history;
    Vec3 fj, tj;
    if (i_first) {
      F += force;
      T += torque_a;
      fj = -force;
      tj = torque_c;
    } else {
      F -= force;
      T += torque_c;
      fj = force;
      tj = torque_a;
    }
    route_share(e, j, fj, tj);
    touch[e] = 1;
    ++tally.pair_contacts;
  }

  // Speed: a pair that has just separated is forgotten (its history and parked share
  // zeroed); the 1-byte touch flag says so without reading the 48-byte history.
  CENTREC_INLINE void forget(std::uint32_t e) const {
    touch[e] = 0;
    hist[e] = ContactHistory{};
    if (slot[e] != PartnerRouting::kDirect) share[slot[e]] = PartnerShare{};
  }

  // The partner's share of entry e: straight into its accumulator when this thread owns
  // every row naming it, else parked in its slot (partner_routing.hpp). Either way the
  // shares are summed in increasing row order.
  CENTREC_INLINE void route_share(std::uint32_t e, long j, Vec3 fj, Vec3 tj) const {
    if (const std::uint32_t s = slot[e]; s == PartnerRouting::kDirect) {
      ACC_F[j] += fj;
      ACC_T[j] += tj;
    } else {
      share[s] = {fj, tj};
    }
  }

  // 3. Row i is done: its force and torque are the partners' direct shares (summed in row
  // order, they come first) plus its own part (pairs, walls, gravity), stored in f_, t_.
  // Rows name only partners of higher index, so a particle with no parked share has its
  // whole force now and no later row reads it: it is integrated here, while its data are
  // in cache (one sweep over the particle arrays per step). Returns the squared
  // displacement of that integration (0 if it waits for the parked pass or has none).
  CENTREC_INLINE double row_total(long i, Vec3 F, Vec3 T, BlockTally& tally) const {
    const Vec3 acc_f = ACC_F[i], acc_t = ACC_T[i];
    ACC_F[i] = {};
    ACC_T[i] = {};
    const bool direct = park_start[i] == park_start[i + 1];
    if (MOT[i] != Motion::free) {  // carried by the drum: forces on it are not needed
      F_out[i] = {};
      T_out[i] = {};
      return direct ? finish(i, Vec3{}, Vec3{}, tally) : 0.0;
    }
    wall_contacts(i, F, T, tally);
    const Vec3 f = acc_f + (F + M[i] * g), t = acc_t + T;
    F_out[i] = f;
    T_out[i] = t;
    return direct ? finish(i, f, t, tally) : 0.0;
  }

  // Contacts of free particle i with its candidate walls (wall_mask, set at each rebuild):
  // the force on i into F, T, the reaction into the block's wall totals.
  CENTREC_INLINE void wall_contacts(long i, Vec3& F, Vec3& T, BlockTally& tally) const {
    const Vec3 xi = X[i];
    const double ri = R[i];
    std::uint32_t mask = wall_mask[i];
    while (mask != 0u) {
      const int wi = __builtin_ctz(mask);
      mask &= mask - 1u;
      const Wall& wall = walls[wi];
      ContactHistory& h = whist[static_cast<std::size_t>(i) * nw + static_cast<std::size_t>(wi)];
      double dist;
      Vec3 nrm, point;
      if (!wall_geometry(wall, xi, dist, nrm, point) || dist >= ri) {
        h = ContactHistory{};
        continue;
      }
      const double delta = ri - dist;
      if (!(delta <= limit * ri)) tally.note_blow_up(i, xi, delta, [&] { return "wall " + std::to_string(wi); });
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
  }

  // 4. A parked particle, once every range is done: its shares summed in row order, then
  // its own part (stored in f_, t_ by row_total), as for the direct ones; then integrated.
  // Parked slots not in contact hold zeros: adding +0.0 leaves a sum bit for bit as
  // skipping it does (the direct sums skip them), because a sum that starts at +0.0 can
  // never be -0.0 in round-to-nearest; for the same reason a parked particle's own part,
  // +0.0 + (F + m g) in row_total, adds as the direct one's F + m g does.
  CENTREC_INLINE double parked_total(long j, BlockTally& tally) const {
    if (MOT[j] == Motion::free) {
      Vec3 sf{}, st{};
      for (std::uint32_t k = park_start[j]; k < park_start[j + 1]; ++k) {
        sf += share[k].force;
        st += share[k].torque;
      }
      F_out[j] = sf + F_out[j];
      T_out[j] = st + T_out[j];
    }
    return finish(j, F_out[j], T_out[j], tally);
  }
};

// Speed records: the mean time a part of a pass waited for the slowest (threads idle).
template <class Parts>
void record_imbalance(const Parts& parts, double& idle) {
  if (parts.size() < 2) return;
  double most = 0.0, sum = 0.0;
  for (const auto& p : parts) {
    most = std::max(most, p.busy);
    sum += p.busy;
  }
  idle += most - sum / static_cast<double>(parts.size());
}

}  // namespace

ListSlack Simulation::compute_forces(bool update_history, AfterForces after) {
  Impl& im = *impl_;
  const long n = static_cast<long>(x_.size());
  const long nblocks = (n + kBlock - 1) / kBlock;
  const std::size_t nw = walls_.size();
  if (im.tallies.size() < static_cast<std::size_t>(nblocks)) im.tallies.resize(static_cast<std::size_t>(nblocks));
  // Row ranges of the pair pass and of the parked pass, one per thread
  // (partner_routing.hpp). Results depend on neither their number nor where they start.
  const long parts = n >= kMinParallelParticles ? std::max(1, threads_) : 1;
  if (im.routing.parts != parts) {
    im.routing = route_partner_shares(im.list, kBlock, parts);
    im.share.assign(im.routing.parked(), PartnerShare{});
  }

  ForcePass pass{x_.data(), v_.data(), w_.data(), r_.data(), m_.data(), id_.data(), mat_.data(), motion_.data(),
                 f_.data(), t_.data(),
                 im.list.start.data(), im.list.nbr.data(), im.list.hist.data(), im.touch.data(),
                 im.routing.slot.data(), im.routing.park_start.data(), im.share.data(), im.acc_f.data(),
                 im.acc_t.data(),
                 walls_.data(), nw, wall_hist_.data(), im.wall_mask.data(), im.half_skin.data(),
                 pc_.data(), n_mat_, im.pz, cfg_.gravity, dt_, blowup_fraction_,
                 cfg_.wall_rolling == WallRolling::relative, update_history, cfg_.pair_batch,
                 n, im.list.reach + kPrefetchMargin, ParticleFinish{}};
  ParticleFinish& finish = pass.finish;
  finish.kick = after != AfterForces::nothing;
  finish.next = after == AfterForces::second_and_next_first_half;
  finish.half = 0.5 * dt_;
  if (finish.next) finish.first = begin_first_half();
  finish.mot = motion_.data();
  finish.inv_m = inv_m_.data();
  finish.inv_inertia = inv_inertia_.data();
  finish.x_build = im.x_build.data();
  finish.x = x_.data();
  finish.v = v_.data();
  finish.w = w_.data();

  // Pass 1: each range of rows on its thread; each pair once, in the row of its lower
  // index (steps 1-3 above).
  // (Each part's largest displacement in its own slot, padded to a cache line.)
  // (Each part's largest displacement and busy time in its own slot, padded to a cache line.)
  struct alignas(64) PartMax {
    ListSlack d2;
    double busy = 0.0;
  };
  std::vector<PartMax> part_max(static_cast<std::size_t>(parts));
  using clock = std::chrono::steady_clock;
  im.team->run(static_cast<int>(parts), [&](int part) {
    const auto t0 = clock::now();
    ListSlack d2;
    for (long b = im.routing.range_start[part]; b < im.routing.range_start[part + 1]; ++b) {
      BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
      tally.reset(nw);
      d2.add(pass.sweep_rows(b * kBlock, std::min(n, (b + 1) * kBlock), tally));
    }
    part_max[static_cast<std::size_t>(part)].d2 = d2;
    part_max[static_cast<std::size_t>(part)].busy = std::chrono::duration<double>(clock::now() - t0).count();
  });
  record_imbalance(part_max, times_.pair_pass_idle);
  // Pass 2: the parked particles (step 4), in ranges of equal numbers of them.
  if (im.routing.parked() > 0) {
    im.team->run(static_cast<int>(parts), [&](int part) {
      const auto t0 = clock::now();
      ListSlack d2;
      for (long b = im.routing.parked_range_start[part]; b < im.routing.parked_range_start[part + 1]; ++b) {
        BlockTally& tally = im.tallies[static_cast<std::size_t>(b)];
        const long j_end = std::min(n, (b + 1) * kBlock);
        for (long j = b * kBlock; j < j_end; ++j)
          if (pass.park_start[j] != pass.park_start[j + 1]) d2.add(pass.parked_total(j, tally), pass.H[j]);
      }
      part_max[static_cast<std::size_t>(part)].d2.add(d2);
      part_max[static_cast<std::size_t>(part)].busy = std::chrono::duration<double>(clock::now() - t0).count();
    });
    record_imbalance(part_max, times_.parked_pass_idle);
  }
  ListSlack moved;
  for (const PartMax& m : part_max) moved.add(m.d2);
  // Step 5: fixed-order reduction over blocks.
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
  return moved;
}

}  // namespace centrec::dem
