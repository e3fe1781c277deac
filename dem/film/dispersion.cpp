#include "dispersion.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace centrec::film {

DispersionEstimator::DispersionEstimator(const DrumFrame& frame, WallDistanceBins bins)
    : frame_(frame), bins_(bins) {
  bins_.check("DispersionEstimator");
  sum_.assign(bins_.count, 0.0);
  sum2_.assign(bins_.count, 0.0);
  n_.assign(bins_.count, 0);
  per_pair_.assign(bins_.count, {});
}

void DispersionEstimator::add_pair(const ParticleArrays& a, const ParticleArrays& b) {
  require_arrays(a, "xyi", "DispersionEstimator (start)");
  require_arrays(b, "xyi", "DispersionEstimator (end)");
  const double tau = b.time - a.time;
  if (!(tau > 0.0)) throw std::invalid_argument("DispersionEstimator: the end snapshot must be later than the start");
  if (tau_ == 0.0) tau_ = tau;
  if (std::fabs(tau - tau_) > 1e-9 * tau_)
    throw std::invalid_argument("DispersionEstimator: every pair must have the same lag");

  std::unordered_map<std::int64_t, std::size_t> end_index;
  end_index.reserve(b.count);
  for (std::size_t j = 0; j < b.count; ++j) end_index.emplace(b.id[j], j);

  std::vector<double> s(bins_.count, 0.0), s2(bins_.count, 0.0);
  std::vector<std::size_t> n(bins_.count, 0);
  for (std::size_t i = 0; i < a.count; ++i) {
    const auto it = end_index.find(a.id[i]);
    if (it == end_index.end()) continue;
    const double r0 = std::hypot(a.x[i], a.y[i]);
    const int k = bins_.index(frame_.radius - r0);
    if (k < 0) continue;
    const double dr = std::hypot(b.x[it->second], b.y[it->second]) - r0;
    s[k] += dr;
    s2[k] += dr * dr;
    ++n[k];
  }
  for (int k = 0; k < bins_.count; ++k) {
    sum_[k] += s[k];
    sum2_[k] += s2[k];
    n_[k] += n[k];
    if (n[k] > 1) {
      const double m = s[k] / n[k];
      per_pair_[k].add((s2[k] / n[k] - m * m) / (2.0 * tau));
    }
  }
}

std::vector<DispersionBin> DispersionEstimator::result() const {
  std::vector<DispersionBin> out(bins_.count);
  for (int k = 0; k < bins_.count; ++k) {
    DispersionBin& d = out[k];
    d.wall_distance_d = bins_.centre_d(k);
    d.samples = n_[k];
    d.pairs = per_pair_[k].count();
    d.coefficient_std = per_pair_[k].stddev();
    if (n_[k] < 2) {
      d.coefficient = d.drift = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const double m = sum_[k] / n_[k];
    d.coefficient = (sum2_[k] / n_[k] - m * m) / (2.0 * tau_);  // variance of dr over 2 tau
    d.drift = m / tau_;
  }
  return out;
}

void DispersionEstimator::save(PackedState& out) const {
  out.put(tau_);
  out.put_all(sum_);
  out.put_all(sum2_);
  out.put_all(n_);
  out.put_all(per_pair_);
}

void DispersionEstimator::load(StateReader& in) {
  const std::size_t bins = sum_.size();
  tau_ = in.get();
  in.get_all(sum_);
  in.get_all(sum2_);
  in.get_all(n_);
  in.get_all(per_pair_);
  if (sum_.size() != bins || sum2_.size() != bins || n_.size() != bins || per_pair_.size() != bins)
    throw std::invalid_argument("DispersionEstimator: saved state has a different bin count");
}

}  // namespace centrec::film
