#pragma once
// A binned profile averaged in two stages: samples accumulate into the current period
// (a drum turn, say); closing the period turns each bin's period mean into one sample of
// the across-period statistics. The paper's profiles are "averaged for 150 turns"; the
// spread between turns is the honest error bar, not the spread between particles.
#include <cstddef>
#include <vector>

#include "dem/film/packed_state.hpp"
#include "dem/film/running_stats.hpp"

namespace centrec::film {

struct ProfileBin {
  double mean = 0.0;        // mean over periods of the period means (NaN if never sampled)
  double stddev = 0.0;      // standard deviation over periods
  std::size_t periods = 0;  // periods in which the bin had samples
  std::size_t samples = 0;  // individual samples over all periods
};

class PeriodProfile {
 public:
  explicit PeriodProfile(int bins = 0) : sum_(bins, 0.0), n_(bins, 0), stats_(bins), total_(bins, 0) {}
  int bins() const { return static_cast<int>(sum_.size()); }
  void add(int bin, double value) {
    sum_[bin] += value;
    ++n_[bin];
  }
  // Closes the current period; bins without samples in it contribute nothing.
  void end_period();
  ProfileBin bin(int k) const;
  std::vector<ProfileBin> all() const;
  void save(PackedState& out) const;  // checkpoints
  void load(StateReader& in);

 private:
  std::vector<double> sum_;
  std::vector<std::size_t> n_;
  std::vector<RunningStats> stats_;
  std::vector<std::size_t> total_;
};

}  // namespace centrec::film
