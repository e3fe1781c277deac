#include "period_profile.hpp"

#include <stdexcept>
#include <string>

namespace centrec::film {

void PeriodProfile::end_period() {
  for (std::size_t k = 0; k < sum_.size(); ++k) {
    if (n_[k]) {
      stats_[k].add(sum_[k] / static_cast<double>(n_[k]));
      total_[k] += n_[k];
    }
    sum_[k] = 0.0;
    n_[k] = 0;
  }
}

void PeriodProfile::save(PackedState& out) const {
  out.put_all(sum_);
  out.put_all(n_);
  out.put_all(stats_);
  out.put_all(total_);
}

void PeriodProfile::load(StateReader& in) {
  const std::size_t bins = sum_.size();
  in.get_all(sum_);
  in.get_all(n_);
  in.get_all(stats_);
  in.get_all(total_);
  if (sum_.size() != bins || n_.size() != bins || stats_.size() != bins || total_.size() != bins)
    throw std::invalid_argument("PeriodProfile: saved state has " + std::to_string(sum_.size()) + " bins, not " +
                                std::to_string(bins));
}

ProfileBin PeriodProfile::bin(int k) const {
  ProfileBin b;
  b.mean = stats_.at(k).mean();
  b.stddev = stats_[k].stddev();
  b.periods = stats_[k].count();
  b.samples = total_[k];
  return b;
}

std::vector<ProfileBin> PeriodProfile::all() const {
  std::vector<ProfileBin> out;
  for (int k = 0; k < bins(); ++k) out.push_back(bin(k));
  return out;
}

}  // namespace centrec::film
