#pragma once
// The film accumulators' state as one flat array of doubles (checkpoints of a sampling
// run, apps/io/checkpoint_h5): PackedState appends values, StateReader reads them back in
// the same order and refuses a short or malformed array. Counts travel as doubles
// (exact below 2^53).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/film/running_stats.hpp"

namespace centrec::film {

struct PackedState {
  std::vector<double> data;
  void put(double v) { data.push_back(v); }
  void put(const RunningStats& s) { data.insert(data.end(), {static_cast<double>(s.count()), s.raw_mean(), s.raw_m2()}); }
  template <class T>
  void put_all(const std::vector<T>& v) {  // length, then the values
    put(static_cast<double>(v.size()));
    for (const T& x : v) put(static_cast<double>(x));
  }
  void put_all(const std::vector<RunningStats>& v) {
    put(static_cast<double>(v.size()));
    for (const RunningStats& s : v) put(s);
  }
};

class StateReader {
 public:
  StateReader(const std::vector<double>& data, std::string what) : data_(data), what_(std::move(what)) {}
  double get() {
    if (pos_ >= data_.size()) throw std::invalid_argument(what_ + ": saved state is too short");
    return data_[pos_++];
  }
  std::size_t count() {
    const double v = get();
    if (!(v >= 0.0 && v < 9.0e15)) throw std::invalid_argument(what_ + ": saved state has a bad count");
    return static_cast<std::size_t>(v);
  }
  RunningStats stats() {
    const std::size_t n = count();
    const double mean = get(), m2 = get();
    return RunningStats::restore(n, mean, m2);
  }
  template <class T>
  void get_all(std::vector<T>& v) {
    v.resize(count());
    for (T& x : v) x = static_cast<T>(get());
  }
  void get_all(std::vector<RunningStats>& v) {
    v.resize(count());
    for (RunningStats& s : v) s = stats();
  }
  void finish() const {
    if (pos_ != data_.size()) throw std::invalid_argument(what_ + ": saved state is too long");
  }

 private:
  const std::vector<double>& data_;
  std::string what_;
  std::size_t pos_ = 0;
};

}  // namespace centrec::film
