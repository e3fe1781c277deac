#pragma once
// Mean and standard deviation of a stream of samples (one sample per snapshot or per
// turn), by Welford's update so long runs lose no precision.
#include <cmath>
#include <cstddef>
#include <limits>

namespace centrec::film {

class RunningStats {
 public:
  void add(double v) {
    ++n_;
    const double delta = v - mean_;
    mean_ += delta / static_cast<double>(n_);
    m2_ += delta * (v - mean_);
  }
  std::size_t count() const { return n_; }
  // Raw Welford state, for checkpoints (dem/film/packed_state.hpp).
  double raw_mean() const { return mean_; }
  double raw_m2() const { return m2_; }
  static RunningStats restore(std::size_t n, double mean, double m2) {
    RunningStats s;
    s.n_ = n;
    s.mean_ = mean;
    s.m2_ = m2;
    return s;
  }
  // NaN when empty, so an unsampled bin cannot pass for a zero.
  double mean() const { return n_ ? mean_ : std::numeric_limits<double>::quiet_NaN(); }
  // Sample standard deviation (n - 1); 0 for a single sample, NaN when empty.
  double stddev() const {
    if (n_ == 0) return std::numeric_limits<double>::quiet_NaN();
    return n_ > 1 ? std::sqrt(m2_ / static_cast<double>(n_ - 1)) : 0.0;
  }

 private:
  std::size_t n_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
};

}  // namespace centrec::film
