#pragma once
// The rolling-resistance sub-models of the contact law (docs/dem_physics.md "Rolling
// resistance"), chosen per material pair (PairInteraction::rolling_model). Each model is
// one row of kRollingModels (its name, its LIGGGHTS and LAMMPS keywords, its own per-pair
// coefficients with their ranges and defaults) and one kernel, RollingKernel<model>,
// written once for a number type N (double, or four AVX2 lanes in dem/pair_batch_avx2.hpp)
// and its 3-vector V, with the lane operations of dem/lane_ops.hpp: the scalar law and the
// AVX2 batch run the same operations in the same order, so they give the same bits. A
// kernel returns the torque M (on i -M, on j +M) and the rolling history it leaves
// (ContactHistory::roll; zero for a model without one).
//
// A new model: its enumerator, its row in kRollingModels (in enumerator order) and its
// RollingKernel specialisation, all in this file. The case reader, the engine's checks,
// same(), the checkpoint, the LIGGGHTS and LAMMPS exports and both force paths walk the
// table; a row without a kernel does not compile, and a row out of order fails the
// static_assert below.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "dem/lane_ops.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

enum class RollingModel : std::uint8_t {
  epsd2,  // elastic-plastic spring, kr = kt R*^2, capped at mu_r R* |Fn| (LIGGGHTS epsd2)
  cdt,    // constant directional torque mu_r R* kn delta against the relative spin (LIGGGHTS cdt)
  sds,    // spring-dashpot-slider on the rolling displacement (LAMMPS GRANULAR `rolling sds`)
};

// A model's own per-pair coefficients (beyond mu_r, which every model reads), by slot:
// PairInteraction::rolling_coefficients[k] is the k-th coefficient of the pair's model.
inline constexpr std::size_t kRollingCoefficientSlots = 2;
using RollingCoefficients = std::array<double, kRollingCoefficientSlots>;

struct RollingCoefficient {
  const char* key;   // the case key beside rolling_model (dem.contacts.*), nullptr = slot unused
  const char* unit;  // SI
  double lowest, highest;
  bool lowest_open;      // (lowest, highest] rather than [lowest, highest]
  double fallback;       // the default of the case key
  const char* liggghts;  // its LIGGGHTS 3.8 per-type-pair property (nullptr where the model has no keyword)
  const char* lammps;    // its place in LAMMPS' `rolling` arguments
  const char* meaning;
};

struct RollingModelInfo {
  RollingModel model;
  const char* name;      // the case's key value (dem.contacts.*.rolling_model)
  const char* liggghts;  // LIGGGHTS 3.8's `rolling_friction` keyword, nullptr = LIGGGHTS has none
  const char* lammps;    // LAMMPS GRANULAR's `rolling` keyword, nullptr = LAMMPS has none
  const char* summary;
  RollingCoefficient coefficients[kRollingCoefficientSlots];
};

inline constexpr double kInfinity = 1e300;

inline constexpr RollingModelInfo kRollingModels[] = {
    {RollingModel::epsd2,
     "epsd2",
     "epsd2",
     nullptr,
     "elastic-plastic spring-dashpot without dashpot: kr = kt R*^2, |Mr| <= mu_r R* |Fn| (Wensrich & Katterfeld 2012)",
     {}},
    {RollingModel::cdt,
     "cdt",
     "cdt",
     nullptr,
     "constant directional torque: |Mr| = mu_r R* kn delta against the relative spin, no history (Zhou et al. 1999)",
     {}},
    {RollingModel::sds,
     "sds",
     nullptr,
     "sds",
     "spring-dashpot-slider on the rolling displacement R* (w_rel x n): |R* n x Fr| <= mu_r R* |Fn| (LAMMPS rolling "
     "sds, Luding 2008)",
     // 100 N/m: EPSD2's k_t of paper Table 1 particles at the settled film's typical overlap
     // (1.5e-3 d, apps/bench/lammps_deck.hpp).
     {{"rolling_stiffness", "N/m", 0.0, kInfinity, true, 100.0, nullptr, "k_roll",
       "sds: spring constant k_roll of the rolling displacement (torque k_roll R*^2 per radian)"},
      {"rolling_damping", "N s/m", 0.0, kInfinity, false, 0.0, nullptr, "gamma_roll",
       "sds: dashpot gamma_roll on the rolling velocity R* (w_rel x n)"}}},
};
inline constexpr std::size_t kRollingModelCount = std::size(kRollingModels);

constexpr bool rows_in_enumerator_order() {
  for (std::size_t k = 0; k < kRollingModelCount; ++k)
    if (static_cast<std::size_t>(kRollingModels[k].model) != k) return false;
  return true;
}
static_assert(rows_in_enumerator_order(), "kRollingModels: row k must be the model of enumerator value k");
constexpr bool liggghts_rows_name_their_properties() {
  for (const RollingModelInfo& i : kRollingModels)
    for (const RollingCoefficient& c : i.coefficients)
      if (i.liggghts && c.key && !c.liggghts) return false;
  return true;
}
static_assert(liggghts_rows_name_their_properties(),
              "kRollingModels: a model LIGGGHTS has names each coefficient's LIGGGHTS property");

inline const RollingModelInfo& rolling_model_info(RollingModel m) {
  for (const RollingModelInfo& i : kRollingModels)
    if (i.model == m) return i;
  return kRollingModels[0];
}

// Whether m has a row (a value cast from an integer may not).
inline bool is_rolling_model(RollingModel m) { return static_cast<std::size_t>(m) < kRollingModelCount; }

// The model of that name, or false.
inline bool rolling_model_named(std::string_view name, RollingModel& out) {
  for (const RollingModelInfo& i : kRollingModels)
    if (name == i.name) {
      out = i.model;
      return true;
    }
  return false;
}

// f(slot, coefficient) for each of model m's own coefficients, in slot order.
template <class F>
void for_each_rolling_coefficient(RollingModel m, F&& f) {
  const RollingModelInfo& i = rolling_model_info(m);
  for (std::size_t k = 0; k < kRollingCoefficientSlots; ++k)
    if (i.coefficients[k].key) f(k, i.coefficients[k]);
}

// The defaults of model m's coefficients (zero in unused slots).
inline RollingCoefficients default_rolling_coefficients(RollingModel m) {
  RollingCoefficients c{};
  for_each_rolling_coefficient(m, [&](std::size_t k, const RollingCoefficient& r) { c[k] = r.fallback; });
  return c;
}

// What a kernel reads: the contact's stiffnesses, overlap, R*, mu_r, normal force, unit
// normal n (from j to i), the relative spin w_rel, the old rolling history, the model's
// own coefficients by slot, and the time step.
template <class N, class V>
struct RollingInput {
  N kt, kn, delta, r_eff, mu_r, fn;
  V n, w_rel, history;
  const N* coefficient;
  double dt;
};

// A RollingInput with N and V taken from the arguments (the AVX2 lane type spelt as a
// template argument would draw GCC's -Wignored-attributes).
template <class N, class V>
RollingInput<N, V> rolling_input(N kt, N kn, N delta, N r_eff, N mu_r, N fn, V n, V w_rel, V history,
                                 const N* coefficient, double dt) {
  return {kt, kn, delta, r_eff, mu_r, fn, n, w_rel, history, coefficient, dt};
}

template <class V>
struct RollingOut {
  V torque;   // Mr: on i -Mr, on j +Mr
  V history;  // the new rolling history
};

// Each model's kernel: `template <class N, class V> static RollingOut<V> torque(const
// RollingInput<N, V>&)`. Not defined for a model without one, so such a model does not
// compile.
template <RollingModel M>
struct RollingKernel;

// EPSD2 (LIGGGHTS 3.x rolling_model_epsd2.h): the spring torque grows with the tangential
// part of the relative spin, Mr += kt R*^2 dt w_t, and is capped at mu_r R* |Fn|. History:
// Mr, N m.
template <>
struct RollingKernel<RollingModel::epsd2> {
  template <class N, class V>
  static RollingOut<V> torque(const RollingInput<N, V>& in) {
    const V w_t = in.w_rel - dot(in.w_rel, in.n) * in.n;
    const V mr = in.history + (in.kt * in.r_eff * in.r_eff * in.dt) * w_t;
    const N mr_max = in.mu_r * in.r_eff * abs_of(in.fn);
    const N mag2 = dot(mr, mr);
    const V capped = select(greater(mag2, mr_max * mr_max), (mr_max / sqrt_of(mag2)) * mr, mr);
    return {capped, capped};
  }
};

// CDT (LIGGGHTS 3.x rolling_model_cdt.h): a torque of size mu_r R* kn delta (the normal
// force's elastic part) along the relative spin, its twisting part removed; none while the
// pair does not spin relative to each other. No history.
template <>
struct RollingKernel<RollingModel::cdt> {
  template <class N, class V>
  static RollingOut<V> torque(const RollingInput<N, V>& in) {
    const N spin = sqrt_of(dot(in.w_rel, in.w_rel));
    const V m = ((in.mu_r * in.kn * in.delta * in.r_eff) / spin) * in.w_rel;
    const V m_t = m - dot(m, in.n) * in.n;
    const V none = zero_like(in.n);
    return {select(greater(spin, zero_like(spin)), m_t, none), none};
  }
};

// SDS (LAMMPS GRANULAR `rolling sds k_roll gamma_roll mu_roll`, gran_sub_mod_rolling):
// the rolling displacement s (m) follows the rolling velocity v_r = R* (w_rel x n) (Wang et
// al. 2015, Particuology 23, eq 31); the rolling force Fr = -k_roll s - gamma_roll v_r is
// capped at mu_r |Fn| (the slider: s then set to the spring length the cap leaves), and the
// torque on i is R* n x Fr. An old s with a normal part (the pair turned) is first turned
// back into the tangent plane with its length kept. History: s, m.
template <>
struct RollingKernel<RollingModel::sds> {
  static constexpr double kTurnTolerance = 1e-10;  // LAMMPS' EPSILON: turn s when |s.n| k > this x mu_r |Fn|
  template <class N, class V>
  static RollingOut<V> torque(const RollingInput<N, V>& in) {
    const N k = in.coefficient[0], gamma = in.coefficient[1];
    const N fr_max = in.mu_r * abs_of(in.fn);
    const V v_roll = in.r_eff * cross(in.w_rel, in.n);
    const N normal = dot(in.history, in.n);
    const V flat = in.history - normal * in.n;
    const N length = sqrt_of(dot(in.history, in.history)), flat_length = sqrt_of(dot(flat, flat));
    const V turned =
        select(greater(flat_length, zero_like(flat_length)), (length / flat_length) * flat, zero_like(flat));
    const V s_old = select(greater(abs_of(normal) * k, kTurnTolerance * fr_max), turned, in.history);
    const V s = s_old + in.dt * v_roll;
    const V fr = (-k) * s + (-gamma) * v_roll;
    const N fr_mag = sqrt_of(dot(fr, fr));
    // The slider: |Fr| held at mu_r |Fn|, s the spring length that leaves (none without a spring length).
    const N k_inv = 1.0 / k, fr_mag_inv = 1.0 / fr_mag;
    const auto has_length = greater(sqrt_of(dot(s, s)), zero_like(fr_mag));
    const V s_slid = (-fr_max * k_inv * fr_mag_inv) * fr + (-gamma * k_inv) * v_roll;
    const V fr_slid = select(has_length, (fr_max * fr_mag_inv) * fr, zero_like(fr));
    const auto slides = greater(fr_mag, fr_max);
    const V f = select(slides, fr_slid, fr);
    const V history = select(slides, select(has_length, s_slid, s), s);
    // Torque on i R* n x Fr = -Mr.
    return {in.r_eff * cross(f, in.n), history};
  }
};

// f(std::integral_constant<RollingModel, m>{}) for the model m: each model's code made
// with its model known at compile time. Returns f's result (value-initialised for a model
// without a row, which the engine's checks refuse).
template <class F, std::size_t... K>
auto with_rolling_model_(RollingModel m, F& f, std::index_sequence<K...>) {
  using R = decltype(f(std::integral_constant<RollingModel, kRollingModels[0].model>{}));
  R r{};
  (void)((m == kRollingModels[K].model ? (r = f(std::integral_constant<RollingModel, kRollingModels[K].model>{}), true)
                                       : false) ||
         ...);
  return r;
}
template <class F>
auto with_rolling_model(RollingModel m, F&& f) {
  return with_rolling_model_(m, f, std::make_index_sequence<kRollingModelCount>{});
}

// f(std::integral_constant<RollingModel, m>{}) for every model m, in table order.
template <class F, std::size_t... K>
void for_each_rolling_model_(F& f, std::index_sequence<K...>) {
  (f(std::integral_constant<RollingModel, kRollingModels[K].model>{}), ...);
}
template <class F>
void for_each_rolling_model(F&& f) {
  for_each_rolling_model_(f, std::make_index_sequence<kRollingModelCount>{});
}

// The pair's rolling torque and history under model m (one model for all lanes).
template <class N, class V>
inline RollingOut<V> rolling_torque(RollingModel m, const RollingInput<N, V>& in) {
  return with_rolling_model(m, [&](auto model) { return RollingKernel<decltype(model)::value>::torque(in); });
}

}  // namespace centrec::dem
