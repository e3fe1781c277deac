// The force pass's AVX2 pair batch (dem/pair_batch_avx2.hpp) against the scalar law
// (pair_contact_input + evaluate_contact): every result the same bits, for random contacts
// (overlaps, velocities and histories over decades, sliding and sticking, rolling capped
// and not, mu_r = 0, mixed materials, every rolling model of dem/rolling_models.hpp alone
// and mixed in the lanes, batches of one to four pairs), and a film run with the batch
// against the same run without it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/pair_batch_avx2.hpp"
#include "film_scene.hpp"

using namespace centrec::dem;

#ifdef CENTREC_PAIR_BATCH

namespace {

namespace pb = centrec::dem::pair_batch;

struct Random {
  std::mt19937_64 rng{20261202};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
  Vec3 direction() { return normalized(Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}); }
  Vec3 vec(double lo, double hi) { return log_uniform(lo, hi) * direction(); }
};

// Material pairs: random moduli, restitution, friction; a fifth with mu_r = 0; the rolling
// models of kRollingModels in turn, each own coefficient random about its default (log-
// uniform over four decades; one of zero default from 1e-6 to 0.1 or zero).
std::vector<PairConstants> random_pairs(Random& rnd, int count) {
  std::vector<PairConstants> pcs;
  for (int k = 0; k < count; ++k) {
    const Material a{rnd.log_uniform(1e6, 1e9), rnd.uniform(0.1, 0.45), rnd.uniform(1000, 8000)};
    const Material b{rnd.log_uniform(1e6, 1e9), rnd.uniform(0.1, 0.45), rnd.uniform(1000, 8000)};
    PairInteraction p{rnd.uniform(0.1, 1.0), rnd.uniform(0.0, 1.2), k % 5 == 0 ? 0.0 : rnd.uniform(0.0, 0.6),
                      kRollingModels[static_cast<std::size_t>(k) % kRollingModelCount].model};
    for_each_rolling_coefficient(p.rolling_model, [&](std::size_t s, const RollingCoefficient& c) {
      p.rolling_coefficients[s] = c.fallback > 0.0      ? rnd.log_uniform(1e-2 * c.fallback, 1e2 * c.fallback)
                                  : rnd.integer(4) == 0 ? 0.0
                                                        : rnd.log_uniform(1e-6, 0.1);
    });
    pcs.push_back(make_pair_constants(a, b, p));
  }
  return pcs;
}

ContactHistory random_history(Random& rnd) {
  if (rnd.integer(8) == 0) return ContactHistory{};  // a new contact
  return {rnd.vec(1e-10, 1e-4), rnd.vec(1e-12, 1e-5)};
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(Vec3 a, Vec3 b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }

double lane(pb::d4 v, int k) {
  alignas(32) double a[pb::kLanes];
  _mm256_store_pd(a, v);
  return a[k];
}
Vec3 lane(pb::V4 v, int k) { return {lane(v.x, k), lane(v.y, k), lane(v.z, k)}; }

}  // namespace

// The law alone: four ContactInputs (pair- and wall-like, arm_j = 0) per call.
TEST(PairBatch, LawLanesAreScalarBitForBit) {
  Random rnd;
  const std::vector<PairConstants> pcs = random_pairs(rnd, 16);
  const double dt = 1e-6;
  long compared = 0, slid = 0, roll_capped = 0;
  long per_model[kRollingModelCount] = {}, alone[kRollingModelCount] = {};
  for (int call = 0; call < 50000; ++call) {
    const PairConstants* pc[pb::kLanes];
    ContactInput in[pb::kLanes];
    ContactHistory old[pb::kLanes];
    const bool one_pair = call % 8 == 0;  // every lane of one material pair: the one-model path
    const int first = rnd.integer(16);
    for (int k = 0; k < pb::kLanes; ++k) {
      pc[k] = &pcs[static_cast<std::size_t>(one_pair ? first : rnd.integer(16))];
      const double ri = rnd.uniform(1e-4, 1e-3), rj = rnd.integer(4) == 0 ? 0.0 : rnd.uniform(1e-4, 1e-3);
      const double delta = rnd.log_uniform(1e-9, 0.05) * ri;
      const double r_eff = rj == 0.0 ? ri : ri * rj / (ri + rj);
      in[k] = {delta, rnd.direction(),         rnd.vec(1e-5, 3.0), rnd.vec(1e-3, 1e3),
               r_eff, rnd.uniform(1e-8, 1e-5), ri - 0.5 * delta,   rj == 0.0 ? 0.0 : rj - 0.5 * delta};
      old[k] = random_history(rnd);
    }
    const auto d = [&](auto f) { return pb::lanes(f(0), f(1), f(2), f(3)); };
    const pb::ConstantLanes cl = pb::constant_lanes(pc[0], pc[1], pc[2], pc[3]);
    const pb::ContactLanes il{d([&](int k) { return in[k].delta; }),     d([&](int k) { return in[k].n; }),
                              d([&](int k) { return in[k].v_contact; }), d([&](int k) { return in[k].w_rel; }),
                              d([&](int k) { return in[k].r_eff; }),     d([&](int k) { return in[k].m_eff; }),
                              d([&](int k) { return in[k].arm_i; }),     d([&](int k) { return in[k].arm_j; })};
    const pb::HistoryLanes hl{d([&](int k) { return old[k].shear; }), d([&](int k) { return old[k].roll; })};
    const pb::ResultLanes r = pb::evaluate_contacts(cl, il, hl, dt);
    for (int k = 0; k < pb::kLanes; ++k) {
      const ContactResult s = evaluate_contact(*pc[k], in[k], old[k], dt);
      ++compared;
      slid += s.sliding;
      ++per_model[static_cast<std::size_t>(pc[k]->rolling)];
      alone[static_cast<std::size_t>(pc[k]->rolling)] += one_pair;
      const double roll_max = pc[k]->mu_r * in[k].r_eff * std::fabs(s.fn);  // EPSD2 on the cap: |Mr| = roll_max
      roll_capped += pc[k]->rolling == RollingModel::epsd2 && pc[k]->mu_r > 0.0 &&
                     std::fabs(norm(s.history.roll) - roll_max) <= 1e-12 * roll_max;
      ASSERT_TRUE(same(lane(r.force, k), s.force)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(lane(r.torque_i, k), s.torque_i)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(lane(r.torque_j, k), s.torque_j)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(lane(r.fn, k), s.fn)) << "call " << call << " lane " << k;
      ASSERT_EQ(lane(r.sliding, k) != 0.0, s.sliding) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(lane(r.history.shear, k), s.history.shear)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(lane(r.history.roll, k), s.history.roll)) << "call " << call << " lane " << k;
    }
  }
  std::printf("law lanes: %ld contacts compared bit for bit, %ld sliding, %ld on the EPSD2 rolling cap\n", compared,
              slid, roll_capped);
  for (std::size_t m = 0; m < kRollingModelCount; ++m) {
    std::printf("  %s: %ld lanes, %ld of them in batches of one material pair\n", kRollingModels[m].name, per_model[m],
                alone[m]);
    EXPECT_GT(per_model[m], compared / 10) << kRollingModels[m].name;
    EXPECT_GT(alone[m], compared / 200) << kRollingModels[m].name;
  }
  EXPECT_GT(slid, compared / 10);
  EXPECT_LT(slid, compared - compared / 10);
  EXPECT_GT(roll_capped, compared / 20);
}

// As the force pass calls it: pairs of particles by index (gathered per lane), one to four
// per batch, against pair_contact_input + evaluate_contact.
TEST(PairBatch, PairBatchesAreScalarBitForBit) {
  Random rnd;
  const int n = 64, n_mat = 3;
  const std::vector<PairConstants> pcs = random_pairs(rnd, n_mat * n_mat);
  std::vector<Vec3> v(n), w(n);
  std::vector<double> r(n), m(n);
  std::vector<int> mat(n);
  for (int p = 0; p < n; ++p) {
    r[static_cast<std::size_t>(p)] = rnd.uniform(2e-4, 1e-3);
    m[static_cast<std::size_t>(p)] = 4000.0 * 4.19 * std::pow(r[static_cast<std::size_t>(p)], 3);
    mat[static_cast<std::size_t>(p)] = rnd.integer(n_mat);
  }
  const pb::ParticleArrays arrays{v.data(), w.data(), r.data(), m.data()};
  const double dt = 2e-6;
  long compared = 0, slid = 0;
  for (int call = 0; call < 50000; ++call) {
    for (int p = 0; p < n; ++p) {  // new velocities each call
      v[static_cast<std::size_t>(p)] = rnd.vec(1e-5, 2.0);
      w[static_cast<std::size_t>(p)] = rnd.vec(1e-3, 2e3);
    }
    const int count = 1 + call % pb::kLanes;
    pb::PairRef batch[pb::kLanes];
    ContactHistory old[pb::kLanes];
    for (int k = 0; k < count; ++k) {
      const long a = rnd.integer(n);
      long c = rnd.integer(n);
      if (c == a) c = (a + 1) % n;
      const double rsum = r[static_cast<std::size_t>(a)] + r[static_cast<std::size_t>(c)];
      const double dist = rsum * (1.0 - rnd.log_uniform(1e-9, 0.03));
      const Vec3 sd = dist * rnd.direction();
      old[k] = random_history(rnd);
      const int ma = mat[static_cast<std::size_t>(a)], mc = mat[static_cast<std::size_t>(c)];
      batch[k] = {sd, norm2(sd), rsum, a, c, &old[k], &pcs[static_cast<std::size_t>(ma * n_mat + mc)]};
    }
    pb::PairResults out;
    pb::evaluate_pairs(batch, count, arrays, dt, out);
    for (int k = 0; k < count; ++k) {
      const pb::PairRef& p = batch[k];
      const auto a = static_cast<std::size_t>(p.a), c = static_cast<std::size_t>(p.c);
      const double dist = std::sqrt(p.dist2);
      const double delta = p.rsum - dist;
      const ContactInput in = pair_contact_input(p.sd, dist, delta, r[a], r[c], m[a], m[c], v[a], v[c], w[a], w[c]);
      const ContactResult s = evaluate_contact(*p.pc, in, *p.old, dt);
      ++compared;
      slid += s.sliding;
      ASSERT_TRUE(same(out.delta[k], delta)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(out.force[k], s.force)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(out.torque_a[k], s.torque_i)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(out.torque_c[k], s.torque_j)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(out.shear[k], s.history.shear)) << "call " << call << " lane " << k;
      ASSERT_TRUE(same(out.roll[k], s.history.roll)) << "call " << call << " lane " << k;
    }
  }
  std::printf("pair batches: %ld pairs compared bit for bit, %ld sliding\n", compared, slid);
  EXPECT_GT(slid, compared / 10);
  EXPECT_LT(slid, compared - compared / 10);
}

// The whole force pass: a settling film of 2000 particles, 1500 steps on 1 and 2 threads
// with the batch and without (SimulationConfig::pair_batch): every particle's x, v, w,
// every wall force and the contact count the same bits.
TEST(PairBatch, FilmRunIsTheScalarRunBitForBit) {
  for (const int threads : {1, 2}) {
    std::vector<Vec3> state[2], walls[2];
    std::size_t contacts[2] = {0, 0};
    for (const bool batch : {true, false}) {
      centrec::dem::testing::FilmScene scene;
      scene.threads = threads;
      scene.length = 6e-3;
      SimulationConfig config = centrec::dem::testing::film_config(scene);
      config.pair_batch = batch;
      Simulation sim(config);
      centrec::dem::testing::build_film(sim, scene, 2000);
      sim.step(1500);
      for (std::size_t i = 0; i < sim.size(); ++i)
        for (const Vec3& u : {sim.positions()[i], sim.velocities()[i], sim.angular_velocities()[i]})
          state[batch].push_back(u);
      for (std::size_t w = 0; w < sim.wall_count(); ++w) walls[batch].push_back(sim.wall_force(static_cast<int>(w)));
      contacts[batch] = sim.neighbour_stats().pair_contacts;
    }
    ASSERT_EQ(state[0].size(), state[1].size());
    std::size_t differing = 0;
    for (std::size_t k = 0; k < state[0].size(); ++k) differing += !same(state[0][k], state[1][k]);
    std::printf("film, %d thread(s): %zu particles after 1500 steps, %zu pair contacts; %zu of %zu vectors differ\n",
                threads, state[0].size() / 3, contacts[1], differing, state[0].size());
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(contacts[1], 1000u);
    EXPECT_EQ(contacts[0], contacts[1]);
    ASSERT_EQ(walls[0].size(), walls[1].size());
    for (std::size_t w = 0; w < walls[0].size(); ++w) EXPECT_TRUE(same(walls[0][w], walls[1][w]));
  }
}

#else

TEST(PairBatch, ScalarBuild) { GTEST_SKIP() << "no AVX2 pair batch in this build (scalar force pass)"; }

#endif
