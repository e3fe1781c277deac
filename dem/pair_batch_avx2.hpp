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
inline d4 sqrt4(d4 a) { return _mm256_sqrt_pd(a); }  // correctly rounded, as std::sqrt
inline d4 fabs4(d4 a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
// a > b per lane: all ones where true, false for NaN as the scalar comparison.
inline d4 greater(d4 a, d4 b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
inline d4 select(d4 mask, d4 a, d4 b) { return _mm256_blendv_pd(b, a, mask); }
inline V4 select(d4 mask, V4 a, V4 b) { return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)}; }

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
};
struct HistoryLanes {
  V4 shear, roll;
};
struct ResultLanes {  // ContactResult; sliding: all ones where the Coulomb cap is active
  V4 force, torque_i, torque_j;
  d4 fn, sliding;
  HistoryLanes history;
};

// pair_contact_input per lane.
inline ContactLanes pair_contact_inputs(V4 sd, d4 dist, d4 delta, d4 ra, d4 rc, d4 ma, d4 mc, V4 va, V4 vc, V4 wa,
                                        V4 wc) {
  const V4 nrm = (1.0 / dist) * sd;
  const d4 arm_a = ra - 0.5 * delta, arm_c = rc - 0.5 * delta;
  const V4 v_contact = (va - vc) - cross(arm_a * wa + arm_c * wc, nrm);  // contact_velocity
  return {delta, nrm, v_contact, wa - wc, ra * rc / (ra + rc), ma * mc / (ma + mc), arm_a, arm_c};
}

// evaluate_contact per lane (hertz_mindlin_coefficients, hertz_normal_force,
// mindlin_tangential, epsd2_rolling_torque inlined in their order).
inline ResultLanes evaluate_contacts(const ConstantLanes& c, const ContactLanes& in, const HistoryLanes& old,
                                     double dt) {
  const d4 root = sqrt4(in.r_eff * in.delta);
  const d4 q = sqrt4(root * in.m_eff);
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
  const d4 ft_max = c.mu * fabs4(out.fn);
  const d4 ft2 = dot(ft, ft);
  out.sliding = greater(ft2, ft_max * ft_max);
  const V4 ft_slide = (ft_max / sqrt4(ft2)) * ft;
  const V4 t_force = select(out.sliding, ft_slide, ft - gamma_t * vt);
  out.history.shear = select(out.sliding, (-1.0 / kt) * ft_slide, shear);
  // Rolling: capped or not, and zero where mu_r <= 0.
  const V4 w_t = in.w_rel - dot(in.w_rel, in.n) * in.n;
  const V4 mr = old.roll + (kt * in.r_eff * in.r_eff * dt) * w_t;
  const d4 mr_max = c.mu_r * in.r_eff * fabs4(out.fn);
  const d4 mag2 = dot(mr, mr);
  const V4 mr_capped = select(greater(mag2, mr_max * mr_max), (mr_max / sqrt4(mag2)) * mr, mr);
  const d4 zero = _mm256_setzero_pd();
  out.history.roll = select(greater(c.mu_r, zero), mr_capped, V4{zero, zero, zero});
  out.force = out.fn * in.n + t_force;
  const V4 nxft = cross(in.n, t_force);
  out.torque_i = (-in.arm_i) * nxft - out.history.roll;
  out.torque_j = (-in.arm_j) * nxft + out.history.roll;
  return out;
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
  ConstantLanes c;
  if (p0.pc == p1.pc && p0.pc == p2.pc && p0.pc == p3.pc) {  // one material pair (the common case)
    const PairConstants& k = *p0.pc;
    c = {_mm256_set1_pd(k.E_eff), _mm256_set1_pd(k.G_eff), _mm256_set1_pd(k.mu),
         _mm256_set1_pd(k.mu_r),  _mm256_set1_pd(k.damp_n), _mm256_set1_pd(k.damp_t)};
  } else {
    const auto field = [&](double PairConstants::*f) { return lanes(p0.pc->*f, p1.pc->*f, p2.pc->*f, p3.pc->*f); };
    c = {field(&PairConstants::E_eff), field(&PairConstants::G_eff), field(&PairConstants::mu),
         field(&PairConstants::mu_r),  field(&PairConstants::damp_n), field(&PairConstants::damp_t)};
  }
  const HistoryLanes old{lanes(p0.old->shear, p1.old->shear, p2.old->shear, p3.old->shear),
                         lanes(p0.old->roll, p1.old->roll, p2.old->roll, p3.old->roll)};
  const d4 dist = sqrt4(lanes(p0.dist2, p1.dist2, p2.dist2, p3.dist2));
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
