#include "period_profile.hpp"

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
