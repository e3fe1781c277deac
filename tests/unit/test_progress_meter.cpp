// The progress line's ETA is this process's pace applied to what is left: a run resumed
// half-way (done_at_start) must not count the simulated time of the process before it as
// done in this one's wall time.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "runs/progress_meter.hpp"

namespace {
// The ETA of the last progress line in `err`.
double last_eta(const std::string& err) {
  const std::size_t at = err.rfind("ETA ");
  double eta = -1.0;
  if (at != std::string::npos) std::sscanf(err.c_str() + at, "ETA %lf", &eta);
  return eta;
}
}  // namespace

TEST(ProgressMeter, AResumedRunsEtaIsItsOwnPaceOverWhatIsLeft) {
  // 10 s of simulated time, 5 s done before this process; it runs 0.1 s of simulated time
  // in 0.2 s of wall time: 4.9 s left at 2 wall s per simulated s is about 9.8 s.
  centrec::runs::ProgressMeter resumed(10.0, 1e-3, 5.0);
  resumed.phase("sampling", "test");
  testing::internal::CaptureStderr();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  resumed.update(5.1, 0.0, 0.0, true);
  const double eta = last_eta(testing::internal::GetCapturedStderr());
  // A fresh run at the same pace: 0.1 s done in 0.2 s, 9.9 s left: about 19.8 s.
  centrec::runs::ProgressMeter fresh(10.0, 1e-3);
  fresh.phase("spin-up", "test");
  testing::internal::CaptureStderr();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  fresh.update(0.1, 0.0, 0.0, true);
  const double eta_fresh = last_eta(testing::internal::GetCapturedStderr());
  std::printf("ETA resumed %.0f s (about 9.8 s), fresh %.0f s (about 19.8 s)\n", eta, eta_fresh);
  EXPECT_GE(eta, 8.0);
  EXPECT_LE(eta, 14.0);  // the sleep may overrun on a loaded machine
  EXPECT_GE(eta_fresh, 17.0);
  EXPECT_LE(eta_fresh, 28.0);
}
