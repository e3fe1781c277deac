#include "runs/interrupt.hpp"

#include <signal.h>

#include <atomic>
#include <cstdio>

namespace centrec::runs {

namespace {
std::atomic<int> g_received{0};
struct sigaction g_previous_int, g_previous_term;

extern "C" void on_signal(int s) {
  g_received.store(s);
  // The next one ends the process: a run that never reaches a safe point can still be stopped.
  ::signal(s, SIG_DFL);
}

std::string time_text(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", t);
  return b;
}
}  // namespace

InterruptGuard::InterruptGuard() {
  g_received.store(0);
  struct sigaction a {};
  a.sa_handler = on_signal;
  sigemptyset(&a.sa_mask);
  sigaction(SIGINT, &a, &g_previous_int);
  sigaction(SIGTERM, &a, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int InterruptGuard::received() { return g_received.load(); }

std::string signal_name(int s) {
  return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "signal " + std::to_string(s);
}

RunInterrupted::RunInterrupted(int signal, double time, std::string checkpoint_dir)
    : std::runtime_error("stopped by " + signal_name(signal) + " at t = " + time_text(time) +
                         " s after writing " + checkpoint_dir + "/checkpoint.h5"),
      signal_(signal),
      dir_(std::move(checkpoint_dir)) {}

OutputsInterrupted::OutputsInterrupted(int signal, const std::string& dir)
    : std::runtime_error(signal_name(signal) + " while the outputs were written: the run is complete in " + dir),
      signal_(signal) {}

}  // namespace centrec::runs
