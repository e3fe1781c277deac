#include "runs/progress_meter.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace centrec::runs {

ProgressMeter::ProgressMeter(double total, double interval, double done_at_start)
    : total_(total),
      done_at_start_(done_at_start),
      tty_(isatty(fileno(stderr)) != 0),
      fixed_interval_(interval > 0.0),
      start_(Clock::now()),
      last_(start_) {
  interval_ = interval > 0.0 ? interval : 2.0;
}

double ProgressMeter::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressMeter::phase(const std::string& name, const std::string& what) {
  finish();
  phase_ = name;
  std::fprintf(stderr, "%s: %s\n", name.c_str(), what.c_str());
  std::fflush(stderr);
}

void ProgressMeter::update(double done, double turns, double particle_steps, bool force,
                           const std::function<std::string()>& status) {
  const auto now = Clock::now();
  const double frac = total_ > 0.0 ? std::min(1.0, done / total_) : 1.0;
  bool due = force;
  if (tty_ || fixed_interval_) {
    due = due || std::chrono::duration<double>(now - last_).count() >= interval_;
  } else if (frac * 10.0 >= next_decile_ - 1e-9) {
    due = true;
  }
  if (!due || (force && done == last_done_)) return;
  last_done_ = done;
  next_decile_ = static_cast<int>(std::floor(frac * 10.0 + 1e-9)) + 1;
  last_ = now;
  const double wall = elapsed();
  // The pace of this process: simulated time since its start over wall time.
  const double ran = done - done_at_start_;
  const double eta = ran > 0.0 ? wall * std::max(0.0, total_ - done) / ran : 0.0;
  const double rate = wall > 0.0 ? particle_steps / wall : 0.0;
  const std::string extra = status ? status() : std::string();
  std::fprintf(stderr, "%s  %-8s %5.1f %%  t = %.3f of %.3f s  turn %.1f%s%s  ETA %.0f s  %.3g particle-steps/s%s",
               tty_ ? "\r\033[K" : "", phase_.c_str(), 100.0 * frac, done, total_, turns, extra.empty() ? "" : "  ",
               extra.c_str(), eta, rate, tty_ ? "" : "\n");
  std::fflush(stderr);
  line_open_ = tty_;
}

void ProgressMeter::set_total(double total, double done) {
  total_ = total;
  const double frac = total_ > 0.0 ? std::min(1.0, done / total_) : 1.0;
  next_decile_ = static_cast<int>(std::floor(frac * 10.0 + 1e-9)) + 1;
}

void ProgressMeter::finish() {
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
}

}  // namespace centrec::runs
