#pragma once
// Speed: the engine's own team of threads for its parallel loops (docs/dem_physics.md
// "Threads"). OpenMP's default wait policy keeps an idle thread spinning at every barrier
// for a long while; on a 2-core machine shared with any other process (a build, a second
// run, the desktop) the spinning thread holds a core the other process then takes from the
// working thread, and a drum step ran 2-4x slower on 2 threads than on 1
// (docs/benchmarks.md "Waiting threads"). A thread of this team spins only briefly
// (kSpinSeconds) for the next job, then sleeps on a condition variable, so a busy machine
// gets the core back, and a quiet one keeps the short hand-over of a spin.
//
// run(parts, f) calls f(p) for p = 0 .. parts-1, part p always on thread p (the caller is
// thread 0), and returns when every part is done: the static schedule of the loops before,
// so which rows a thread works on depends only on the part, never on timing. Results never
// depend on the team (the force pass sums in a fixed order, docs/architecture.md).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace centrec::dem {

class ThreadTeam {
 public:
  // How long a waiting thread spins before it sleeps: a few list-entry passes of a small
  // film, far below a step (~1-10 ms), far above a futex wake-up (~10-50 us).
  static constexpr double kSpinSeconds = 50e-6;

  explicit ThreadTeam(int threads);  // threads >= 1; threads - 1 workers are started
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }

  // f(p) for p in [0, parts), part p on thread p; parts <= size() (more is refused).
  template <class F>
  void run(int parts, F&& f) {
    if (parts <= 1) {
      if (parts == 1) f(0);
      return;
    }
    using Fn = std::remove_reference_t<F>;
    dispatch(parts, [](void* c, int p) { (*static_cast<Fn*>(c))(p); }, &f);
  }

 private:
  void dispatch(int parts, void (*fn)(void*, int), void* ctx);
  void work(int index);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::atomic<std::uint64_t> generation_{0};  // bumped once per job
  std::atomic<int> remaining_{0};             // workers still on the current job
  std::atomic<bool> stop_{false};
  void (*fn_)(void*, int) = nullptr;
  void* ctx_ = nullptr;
  int parts_ = 0;
};

// Part p of `parts` equal contiguous ranges of [0, n): [range_begin(n, parts, p), range_begin(n, parts, p + 1)).
inline long range_begin(long n, long parts, long p) { return n * p / parts; }

}  // namespace centrec::dem
