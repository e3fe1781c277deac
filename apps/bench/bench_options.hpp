#pragma once
// Command line of centrec_bench_film.
#include <string>
#include <vector>

namespace centrec::bench {

struct BenchOptions {
  std::vector<long> sizes{10000, 50000, 200000};  // target N (rounded to whole lattice rows)
  std::vector<int> threads{1, 2};                 // centrec threads = LIGGGHTS / LAMMPS ranks
  long steps = 1000;                              // per timed phase
  // When > 0: every size's timed phase is this many particle-steps (steps = round(P / N),
  // overrides steps), so the small film's phases last as long as the large one's and a
  // short slow spell of a shared machine weighs the same on every size.
  double phase_particle_steps = 0.0;
  // When > 0: every size times the same simulated window (repeats x steps after the
  // settle) and a small film replays that window from its post-settle state until it has
  // timed about P particle-steps, so every size does equal work in the same film state.
  double replay_particle_steps = 0.0;
  long settle_steps = 2000;
  int repeats = 3;
  std::vector<int> repeats_per_size;             // optional, overrides repeats per size
  bool liggghts = true;
  bool lammps = true;
  bool centrec = true;
  bool interleave = false;                        // centrec: alternate the sizes' timed phases
  double liggghts_skin_d = 0.4;                   // neighbour skin / d
  double lammps_skin_d = 0.4;
  double centrec_skin_d = 0.4;
  int stl_facets = 720;                           // facets around the cylinder
  std::string out = "bench-film";
  std::string liggghts_exe = "liggghts";
  std::string lammps_exe = "lmp";
  std::string mpirun = "mpirun";
};

// Steps of one timed phase of a film of n particles.
long timed_steps_for(const BenchOptions& o, long n);

// Timed windows (from the post-settle state) of size index si with n particles: 1, or
// round(P / (n x steps x repeats)) with --replay-particle-steps P.
int replays_for(const BenchOptions& o, long n, std::size_t si);

// Timed phases per window of size index si (--repeats or --repeats-per-size).
int repeats_of(const BenchOptions& o, std::size_t si);

// Parses argv; prints help and exits(0) on --help; throws std::invalid_argument on errors.
BenchOptions parse_bench_options(int argc, char** argv);

}  // namespace centrec::bench
