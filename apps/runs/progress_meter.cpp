#include "runs/progress_meter.hpp"

#include <unistd.h>

#include <cstdio>

namespace centrec::runs {

ProgressMeter::ProgressMeter(double total, double interval)
    : total_(total), tty_(isatty(fileno(stderr)) != 0), start_(Clock::now()), last_(start_) {
  interval_ = interval > 0.0 ? interval : (tty_ ? 0.5 : 10.0);
}

double ProgressMeter::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressMeter::update(double done, double turns, double particle_steps, bool force) {
  const auto now = Clock::now();
  if (!force && std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  const double wall = elapsed();
  const double frac = total_ > 0.0 ? done / total_ : 1.0;
  const double eta = frac > 0.0 ? wall * (1.0 - frac) / frac : 0.0;
  const double rate = wall > 0.0 ? particle_steps / wall : 0.0;
  std::fprintf(stderr, "%s%5.1f %%  t = %.4f s  turns = %.2f  ETA %.0f s  %.3g particle-steps/s%s",
               tty_ ? "\r" : "", 100.0 * frac, done, turns, eta, rate, tty_ ? "   " : "\n");
  std::fflush(stderr);
}

void ProgressMeter::finish() {
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace centrec::runs
