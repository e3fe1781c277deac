#pragma once
// Speed: the particle-pair contact law four pairs at a time, in the lanes of AVX2
// registers (the batched pair row of the force pass, simulation_forces.cpp).
// pair_contact_input + evaluate_contact (contact_law.hpp) remain the one reference law;
// this file repeats their arithmetic lane by lane, operation for operation and in the
// same order: no fused multiply-add (the build has -ffp-contract=off), no approximate
// reciprocal or square root, no reassociation. Where the scalar law branches (Coulomb
// cap, rolling cap, mu_r > 0) both branches are computed and each lane keeps the one the
// scalar code takes. A lane's IEEE arithmetic being a scalar register's, every result is
// the scalar one bit for bit (tests/dem/test_pair_batch.cpp): trajectories, outputs and
// thread-count determinism do not depend on the path.
// Compiled when the target has AVX2, unless the CENTREC_SIMD option is off; the force
// pass is scalar otherwise. Wall contacts are always scalar.
#if defined(__AVX2__) && !defined(CENTREC_NO_SIMD)
#define CENTREC_PAIR_BATCH 1
#include <immintrin.h>

#include "dem/contact_law.hpp"

namespace centrec::dem::pair_batch {

constexpr int kLanes = 4;

// Four doubles. GCC and Clang apply + - * / and unary minus lane-wise, and a scalar
// operand to every lane.
using d4 = __m256d;

struct V4 {
  d4 x, y, z;
};

inline V4 operator+(V4 a, V4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V4 operator-(V4 a, V4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V4 operator*(d4 s, V4 a) { return {s * a.x, s * a.y, s * a.z}; }
inline V4 operator*(double s, V4 a) { return {s * a.x, s * a.y, s * a.z}; }
inline d4 dot(V4 a, V4 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V4 cross(V4 a, V4 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
// The lane operations of dem/lane_ops.hpp (sqrt_of, abs_of, greater, select, zero_like)
// for d4, and for V4 here (found by argument-dependent lookup from the shared texts).
using centrec::dem::abs_of;
using centrec::dem::greater;
using centrec::dem::select;
using centrec::dem::sqrt_of;
using centrec::dem::zero_like;
inline V4 select(d4 mask, V4 a, V4 b) {
  return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)};
}
inline V4 zero_like(V4) { return {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()}; }

inline d4 lanes(double a0, double a1, double a2, double a3) { return _mm256_set_pd(a3, a2, a1, a0); }
inline V4 lanes(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& a3) {
  return {lanes(a0.x, a1.x, a2.x, a3.x), lanes(a0.y, a1.y, a2.y, a3.y), lanes(a0.z, a1.z, a2.z, a3.z)};
}

// ContactInput, PairConstants and ContactHistory of four contacts, lane k from contact k.
struct ContactLanes {
  d4 delta;
  V4 n, v_contact, w_rel;
  d4 r_eff, m_eff, arm_i, arm_j;
};
struct ConstantLanes {
  d4 E_eff, G_eff, mu, mu_r, damp_n, damp_t;
  d4 rolling_coefficients[kRollingCoefficientSlots];
  RollingModel model;  // every lane's rolling model, unless models_differ
  bool models_differ;
  d4 model_lanes;  // where models_differ: each lane's RollingModel as a number
};
struct HistoryLanes {
  V4 shear, roll;
};
struct ResultLanes {  // ContactResult; sliding: all ones where the Coulomb cap is active
  V4 force, torque_i, torque_j;
  d4 fn, sliding;
  HistoryLanes history;
};

// The constants of four contacts' material pairs, lane k from pk.
inline ConstantLanes constant_lanes(const PairConstants* p0, const PairConstants* p1, const PairConstants* p2,
                                    const PairConstants* p3) {
  ConstantLanes c;
  if (p0 == p1 && p0 == p2 && p0 == p3) {  // one material pair (the common case)
    const PairConstants& k = *p0;
    c = {_mm256_set1_pd(k.E_eff),
         _mm256_set1_pd(k.G_eff),
         _mm256_set1_pd(k.mu),
         _mm256_set1_pd(k.mu_r),
         _mm256_set1_pd(k.damp_n),
         _mm256_set1_pd(k.damp_t),
         {},
         k.rolling,
         false,
         _mm256_setzero_pd()};
    for (std::size_t s = 0; s < kRollingCoefficientSlots; ++s)
      c.rolling_coefficients[s] = _mm256_set1_pd(k.rolling_coefficients[s]);
    return c;
  }
  const auto field = [&](double PairConstants::*f) { return lanes(p0->*f, p1->*f, p2->*f, p3->*f); };
  const auto model = [](const PairConstants* k) { return static_cast<double>(k->rolling); };
  const RollingModel m = p0->rolling;
  const bool differ = p1->rolling != m || p2->rolling != m || p3->rolling != m;
  c = {field(&PairConstants::E_eff),
       field(&PairConstants::G_eff),
       field(&PairConstants::mu),
       field(&PairConstants::mu_r),
       field(&PairConstants::damp_n),
       field(&PairConstants::damp_t),
       {},
       m,
       differ,
       lanes(model(p0), model(p1), model(p2), model(p3))};
  for (std::size_t s = 0; s < kRollingCoefficientSlots; ++s)
    c.rolling_coefficients[s] = lanes(p0->rolling_coefficients[s], p1->rolling_coefficients[s],
                                      p2->rolling_coefficients[s], p3->rolling_coefficients[s]);
  return c;
}

// pair_contact_input per lane.
inline ContactLanes pair_contact_inputs(V4 sd, d4 dist, d4 delta, d4 ra, d4 rc, d4 ma, d4 mc, V4 va, V4 vc, V4 wa,
                                        V4 wc) {
  const V4 nrm = (1.0 / dist) * sd;
  const d4 arm_a = ra - 0.5 * delta, arm_c = rc - 0.5 * delta;
  const V4 v_contact = (va - vc) - cross(arm_a * wa + arm_c * wc, nrm);  // contact_velocity
  return {delta, nrm, v_contact, wa - wc, ra * rc / (ra + rc), ma * mc / (ma + mc), arm_a, arm_c};
}

// evaluate_contact per lane (hertz_mindlin_coefficients, hertz_normal_force,
// mindlin_tangential inlined in their order; the rolling model's own text).
// Speed: the law written once, made for each rolling model (and for lanes of several) so
// the lanes of a batch of one model run that model's straight-line code.
constexpr int kMixedModels = -1;  // Model: a RollingModel's value, or lanes of several

template <int Model>
inline ResultLanes evaluate_contacts_as(const ConstantLanes& c, const ContactLanes& in, const HistoryLanes& old,
                                        double dt) {
  const d4 root = sqrt_of(in.r_eff * in.delta);
  const d4 q = sqrt_of(root * in.m_eff);
  const d4 kn = (4.0 / 3.0) * c.E_eff * root, kt = 8.0 * c.G_eff * root;
  const d4 gamma_n = c.damp_n * q, gamma_t = c.damp_t * q;
  const d4 vn = dot(in.v_contact, in.n);
  const V4 vt = in.v_contact - vn * in.n;
  ResultLanes out;
  out.fn = kn * in.delta - gamma_n * vn;
  // Tangential: sticking and sliding both computed, the cap's choice kept.
  V4 shear = old.shear + dt * vt;
  shear = shear - dot(shear, in.n) * in.n;
  const V4 ft = (-kt) * shear;
  const d4 ft_max = c.mu * abs_of(out.fn);
  const d4 ft2 = dot(ft, ft);
  out.sliding = greater(ft2, ft_max * ft_max);
  const V4 ft_slide = (ft_max / sqrt_of(ft2)) * ft;
  const V4 t_force = select(out.sliding, ft_slide, ft - gamma_t * vt);
  out.history.shear = select(out.sliding, (-1.0 / kt) * ft_slide, shear);
  // Rolling (dem/rolling_models.hpp, the scalar law's text): each lane's model, and zero
  // where mu_r <= 0. Lanes of one model (the common case) run that model only; lanes of
  // several run every model of the table, each lane keeping its own model's result.
  const auto roll_in = rolling_input(kt, kn, in.delta, in.r_eff, c.mu_r, out.fn, in.n, in.w_rel, old.roll,
                                     &c.rolling_coefficients[0], dt);
  RollingOut<V4> roll;
  if constexpr (Model == kMixedModels) {
    roll = {zero_like(in.n), zero_like(in.n)};
    for_each_rolling_model([&](auto model) {
      const RollingOut<V4> r = RollingKernel<decltype(model)::value>::torque(roll_in);
      const d4 mine = _mm256_cmp_pd(c.model_lanes, _mm256_set1_pd(static_cast<double>(model.value)), _CMP_EQ_OQ);
      roll = {select(mine, r.torque, roll.torque), select(mine, r.history, roll.history)};
    });
  } else {
    roll = RollingKernel<static_cast<RollingModel>(Model)>::torque(roll_in);
  }
  const d4 zero = _mm256_setzero_pd();
  const d4 rolls = greater(c.mu_r, zero);
  const V4 torque_r = select(rolls, roll.torque, zero_like(roll.torque));
  out.history.roll = select(rolls, roll.history, zero_like(roll.history));
  out.force = out.fn * in.n + t_force;
  const V4 nxft = cross(in.n, t_force);
  out.torque_i = (-in.arm_i) * nxft - torque_r;
  out.torque_j = (-in.arm_j) * nxft + torque_r;
  return out;
}

inline ResultLanes evaluate_contacts(const ConstantLanes& c, const ContactLanes& in, const HistoryLanes& old,
                                     double dt) {
  if (c.models_differ) return evaluate_contacts_as<kMixedModels>(c, in, old, dt);
  return with_rolling_model(c.model, [&](auto model) {
    return evaluate_contacts_as<static_cast<int>(decltype(model)::value)>(c, in, old, dt);
  });
}

// One particle pair in contact, as the pair row found it: a and c in canonical operand
// order (a the lower id), sd = x_a - x_c (minimum image), dist2 = |sd|^2 < rsum^2.
struct PairRef {
  Vec3 sd;
  double dist2, rsum;
  long a, c;
  const ContactHistory* old;
  const PairConstants* pc;
};

// The particle arrays the law reads.
struct ParticleArrays {
  const Vec3 *v, *w;
  const double *r, *m;
};

// Four results, lane k in [k].
struct Vec3Lanes {
  alignas(32) double x[kLanes], y[kLanes], z[kLanes];
  Vec3 operator[](int k) const { return {x[k], y[k], z[k]}; }
  void store(V4 a) {
    _mm256_store_pd(x, a.x);
    _mm256_store_pd(y, a.y);
    _mm256_store_pd(z, a.z);
  }
};
struct PairResults {
  alignas(32) double delta[kLanes];
  Vec3Lanes force, torque_a, torque_c, shear, roll;  // ContactResult's, a as i
};

// Pairs p[0 .. count-1] (1 <= count <= 4) evaluated as pair_contact_input +
// evaluate_contact evaluate them: dist = sqrt(dist2), delta = rsum - dist. Lanes past
// count repeat pair 0; their results are not to be read.
inline void evaluate_pairs(const PairRef* p, int count, const ParticleArrays& s, double dt, PairResults& out) {
  const PairRef& p0 = p[0];
  const PairRef& p1 = p[count > 1 ? 1 : 0];
  const PairRef& p2 = p[count > 2 ? 2 : 0];
  const PairRef& p3 = p[count > 3 ? 3 : 0];
  const auto gather = [&](const auto* a, long PairRef::*idx) {
    return lanes(a[p0.*idx], a[p1.*idx], a[p2.*idx], a[p3.*idx]);
  };
  const ConstantLanes c = constant_lanes(p0.pc, p1.pc, p2.pc, p3.pc);
  const HistoryLanes old{lanes(p0.old->shear, p1.old->shear, p2.old->shear, p3.old->shear),
                         lanes(p0.old->roll, p1.old->roll, p2.old->roll, p3.old->roll)};
  const d4 dist = sqrt_of(lanes(p0.dist2, p1.dist2, p2.dist2, p3.dist2));
  const d4 delta = lanes(p0.rsum, p1.rsum, p2.rsum, p3.rsum) - dist;
  const ContactLanes in = pair_contact_inputs(
      lanes(p0.sd, p1.sd, p2.sd, p3.sd), dist, delta, gather(s.r, &PairRef::a), gather(s.r, &PairRef::c),
      gather(s.m, &PairRef::a), gather(s.m, &PairRef::c), gather(s.v, &PairRef::a), gather(s.v, &PairRef::c),
      gather(s.w, &PairRef::a), gather(s.w, &PairRef::c));
  const ResultLanes r = evaluate_contacts(c, in, old, dt);
  _mm256_store_pd(out.delta, delta);
  out.force.store(r.force);
  out.torque_a.store(r.torque_i);
  out.torque_c.store(r.torque_j);
  out.shear.store(r.history.shear);
  out.roll.store(r.history.roll);
}

}  // namespace centrec::dem::pair_batch

#endif
