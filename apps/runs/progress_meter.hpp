#pragma once
// Progress of a long run (docs/outputs.md), on stderr: the phase (spin-up, sampling, ...),
// percent, simulated time, turns, a caller's status (outlet vs inlet flow), ETA and
// particle-steps/s. On a terminal one line updated every 2 s; otherwise a plain line at every
// 10 % of the run (and at each phase change), so a log stays short. run.progress_interval
// (wall seconds, > 0) replaces both with a fixed interval.
#include <chrono>
#include <functional>
#include <string>

namespace centrec::runs {

class ProgressMeter {
 public:
  // total: simulated seconds to run; interval: wall seconds between lines (0 = as above);
  // done_at_start: simulated seconds done before this process (a resumed run's), which the
  // ETA leaves out of the pace.
  ProgressMeter(double total, double interval, double done_at_start = 0.0);
  // Starts a named phase: one line naming it (and what it is for), then its progress lines.
  void phase(const std::string& name, const std::string& what);
  // Report if due: sim time done, turns done, particle-steps since the start; status() is
  // called only when a line is printed.
  void update(double done, double turns, double particle_steps, bool force = false,
              const std::function<std::string()>& status = {});
  // The run got longer (a spin-up extended until steady): percentages and ETA from `total`,
  // with `done` reached so far.
  void set_total(double total, double done);
  void finish();
  double elapsed() const;

 private:
  using Clock = std::chrono::steady_clock;
  double total_, interval_, done_at_start_;
  bool tty_, fixed_interval_;
  bool line_open_ = false;  // a terminal line being updated in place, not yet ended
  int next_decile_ = 1;
  double last_done_ = -1.0;  // simulated time of the last line printed
  std::string phase_;
  Clock::time_point start_, last_;
};

}  // namespace centrec::runs
