#pragma once
// The rolling-resistance sub-models of the contact law (docs/dem_physics.md "Rolling
// resistance"), chosen per material pair (PairInteraction::rolling_model). Each model is
// one text written for a number type N (double, or four AVX2 lanes in
// dem/pair_batch_avx2.hpp) and its 3-vector V, with the lane operations of
// dem/lane_ops.hpp: the scalar law and the AVX2 batch run the same operations in the same
// order, so they give the same bits. A model returns the torque M (on i -M, on j +M) and
// the rolling history it leaves (ContactHistory::roll; zero for a model without one).
//
// A new model: its enumerator, its row in kRollingModels, its function below and its case
// in rolling_torque (and in pair_batch::evaluate_contacts' dispatch).
#include <cstdint>
#include <string_view>

#include "dem/lane_ops.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

enum class RollingModel : std::uint8_t {
  epsd2,  // elastic-plastic spring, kr = kt R*^2, capped at mu_r R* |Fn| (LIGGGHTS epsd2)
  cdt,    // constant directional torque mu_r R* kn delta against the relative spin (LIGGGHTS cdt)
};

struct RollingModelInfo {
  RollingModel model;
  const char* name;      // the case's key value (dem.contacts.*.rolling_model)
  const char* liggghts;  // LIGGGHTS 3.8's `rolling_friction` keyword
  const char* summary;
};

inline constexpr RollingModelInfo kRollingModels[] = {
    {RollingModel::epsd2, "epsd2", "epsd2",
     "elastic-plastic spring-dashpot without dashpot: kr = kt R*^2, |Mr| <= mu_r R* |Fn| (Wensrich & Katterfeld 2012)"},
    {RollingModel::cdt, "cdt", "cdt",
     "constant directional torque: |Mr| = mu_r R* kn delta against the relative spin, no history (Zhou et al. 1999)"},
};

inline const RollingModelInfo& rolling_model_info(RollingModel m) {
  for (const RollingModelInfo& i : kRollingModels)
    if (i.model == m) return i;
  return kRollingModels[0];
}

// The model of that name, or false.
inline bool rolling_model_named(std::string_view name, RollingModel& out) {
  for (const RollingModelInfo& i : kRollingModels)
    if (name == i.name) {
      out = i.model;
      return true;
    }
  return false;
}

template <class V>
struct RollingOut {
  V torque;   // Mr: on i -Mr, on j +Mr
  V history;  // the new rolling history
};

// EPSD2 (LIGGGHTS 3.x rolling_model_epsd2.h): the spring torque grows with the tangential
// part of the relative spin, Mr += kt R*^2 dt w_t, and is capped at mu_r R* |Fn|.
template <class N, class V>
inline RollingOut<V> epsd2_rolling(N kt, N r_eff, N mu_r, N fn, V n, V w_rel, V mr_old, double dt) {
  const V w_t = w_rel - dot(w_rel, n) * n;
  const V mr = mr_old + (kt * r_eff * r_eff * dt) * w_t;
  const N mr_max = mu_r * r_eff * abs_of(fn);
  const N mag2 = dot(mr, mr);
  const V capped = select(greater(mag2, mr_max * mr_max), (mr_max / sqrt_of(mag2)) * mr, mr);
  return {capped, capped};
}

// CDT (LIGGGHTS 3.x rolling_model_cdt.h): a torque of size mu_r R* kn delta (the normal
// force's elastic part) along the relative spin, its twisting part removed; none while the
// pair does not spin relative to each other.
template <class N, class V>
inline RollingOut<V> cdt_rolling(N kn, N delta, N r_eff, N mu_r, V n, V w_rel) {
  const N spin = sqrt_of(dot(w_rel, w_rel));
  const V m = ((mu_r * kn * delta * r_eff) / spin) * w_rel;
  const V m_t = m - dot(m, n) * n;
  const V none = zero_like(n);
  return {select(greater(spin, zero_like(spin)), m_t, none), none};
}

// The pair's rolling torque and history under model m (one model for all lanes).
template <class N, class V>
inline RollingOut<V> rolling_torque(RollingModel m, N kt, N kn, N delta, N r_eff, N mu_r, N fn, V n, V w_rel, V mr_old,
                                    double dt) {
  switch (m) {
    case RollingModel::cdt:
      return cdt_rolling(kn, delta, r_eff, mu_r, n, w_rel);
    case RollingModel::epsd2:
      break;
  }
  return epsd2_rolling(kt, r_eff, mu_r, fn, n, w_rel, mr_old, dt);
}

}  // namespace centrec::dem
