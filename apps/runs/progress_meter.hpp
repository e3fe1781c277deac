#pragma once
// Progress of a long run (docs/outputs.md): percent, simulated time, turns, ETA and
// particle-steps/s; an updating line on a terminal, plain log lines otherwise.
#include <chrono>
#include <cstdint>
#include <string>

namespace centrec::runs {

class ProgressMeter {
 public:
  // total: simulated seconds to run; interval: wall seconds between log lines (0 = auto).
  ProgressMeter(double total, double interval);
  // Report if due: sim time done, turns done, particle-steps since the start.
  void update(double done, double turns, double particle_steps, bool force = false);
  void finish();
  double elapsed() const;

 private:
  using Clock = std::chrono::steady_clock;
  double total_, interval_;
  bool tty_;
  Clock::time_point start_, last_;
};

}  // namespace centrec::runs
