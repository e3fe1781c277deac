#include "dem/thread_team.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CENTREC_CPU_RELAX() _mm_pause()
#else
#define CENTREC_CPU_RELAX() std::this_thread::yield()
#endif

namespace centrec::dem {

namespace {

// Spins until done() or kSpinSeconds have passed; returns done().
template <class Done>
bool spin_until(Done done) {
  using clock = std::chrono::steady_clock;
  const auto until = clock::now() + std::chrono::duration<double>(ThreadTeam::kSpinSeconds);
  for (;;) {
    for (int k = 0; k < 64; ++k) {
      if (done()) return true;
      CENTREC_CPU_RELAX();
    }
    if (clock::now() >= until) return done();
  }
}

}  // namespace

ThreadTeam::ThreadTeam(int threads) {
  if (threads < 1) throw std::invalid_argument("ThreadTeam: need at least 1 thread, got " + std::to_string(threads));
  workers_.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t) workers_.emplace_back([this, t] { work(t); });
}

ThreadTeam::~ThreadTeam() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_.store(true, std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

void ThreadTeam::dispatch(int parts, void (*fn)(void*, int), void* ctx) {
  if (parts > size())
    throw std::invalid_argument("ThreadTeam::run: " + std::to_string(parts) + " parts for a team of " +
                                std::to_string(size()));
  fn_ = fn;
  ctx_ = ctx;
  parts_ = parts;
  remaining_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  {
    // Under the lock, so a worker that has just found the old generation and is about to
    // sleep cannot miss the wake-up.
    std::lock_guard<std::mutex> lock(mutex_);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  fn(ctx, 0);
  const auto finished = [&] { return remaining_.load(std::memory_order_acquire) == 0; };
  if (!spin_until(finished)) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, finished);
  }
}

void ThreadTeam::work(int index) {
  std::uint64_t seen = 0;
  for (;;) {
    const auto published = [&] { return generation_.load(std::memory_order_acquire) != seen; };
    if (!spin_until(published)) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, published);
    }
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_relaxed)) return;
    if (index < parts_) fn_(ctx_, index);
    if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard<std::mutex> lock(mutex_);  // the caller may be between its check and its sleep
      done_.notify_one();
    }
  }
}

}  // namespace centrec::dem
