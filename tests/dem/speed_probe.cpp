// Rough speed probe of the engine on a settled dense film (not a test; the project's
// benchmark against LIGGGHTS lives in apps/bench).
// Usage: dem_speed_probe N [steps] [skin_fraction] [settle_steps]
#include <omp.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>

#include "film_scene.hpp"

using namespace centrec::dem;
using namespace centrec::dem::testing;

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
  const long steps = argc > 2 ? std::strtol(argv[2], nullptr, 10) : 2000;
  FilmScene scene;
  SimulationConfig cfg = film_config(scene);
  if (argc > 3) cfg.skin_fraction = std::atof(argv[3]);
  Simulation sim(cfg);
  build_film(sim, scene, n);
  sim.step(argc > 4 ? std::strtol(argv[4], nullptr, 10) : 3000);  // settle
  for (int threads : {1, 2}) {
    sim.set_threads(threads);
    const auto before = sim.neighbour_stats();
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    sim.step(steps);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;  // all threads; robust to a busy machine
    const auto st = sim.neighbour_stats();
    std::printf("N=%zu threads=%d: %.3g particle-steps/s (%.1f ns per particle-step), %.2f contacts/particle, "
                "CPU %.1f ns per particle-step, %.1f list entries/particle, %zu rebuilds in %ld steps, %.0f bytes/particle\n",
                sim.size(), threads, sim.size() * steps / secs, 1e9 * secs / (sim.size() * steps),
                st.contacts_per_particle(), 1e9 * cpu / (sim.size() * steps), double(st.list_entries) / sim.size(), st.rebuilds - before.rebuilds, steps,
                double(sim.memory_bytes()) / sim.size());
  }
  return 0;
}
