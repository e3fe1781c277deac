#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a DEM run (docs/reliability.md): while an
// InterruptGuard lives, the first signal only sets a flag, which the run polls at its next
// safe point (after a spin-up chunk or a sampled turn) to write a checkpoint and stop with
// RunInterrupted; a second signal ends the process at once (the default action).
#include <stdexcept>
#include <string>

namespace centrec::runs {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  // The signal received since the last guard was installed (0 = none); it stays readable
  // after that guard is gone.
  static int received();
};

// A run stopped by a signal after writing its checkpoint.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(int signal, double time, std::string checkpoint_dir);
  int signal() const { return signal_; }
  const std::string& checkpoint_dir() const { return dir_; }

 private:
  int signal_;
  std::string dir_;
};

// A signal that arrived while a finished run wrote its outputs: they were written first,
// so the run is complete in `dir`; what would have followed (plots, the thermal stage of a
// coupled run) is not done.
class OutputsInterrupted : public std::runtime_error {
 public:
  OutputsInterrupted(int signal, const std::string& dir);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// "SIGINT", "SIGTERM" or "signal N".
std::string signal_name(int signal);

}  // namespace centrec::runs
