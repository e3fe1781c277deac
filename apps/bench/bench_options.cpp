#include "bench/bench_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "cli/command_line.hpp"

namespace centrec::bench {
namespace {

const char* kDescription =
    "centrec_bench_film: DEM speed of centrec vs LIGGGHTS 3.8 and LAMMPS on a settled particle film\n"
    "in the D12 drum. All engines start from the same lattice file, settle, then run\n"
    "timed phases; the median phase gives particle-steps/s.";

// Numbers are read as positive reals ("1e4" is a size too) and rounded down where the
// option counts something, as they always were.
template <class T>
std::vector<T> whole(const std::vector<double>& v) {
  std::vector<T> out;
  for (double x : v) out.push_back(static_cast<T>(x));
  return out;
}

}  // namespace

long timed_steps_for(const BenchOptions& o, long n) {
  if (o.phase_particle_steps <= 0.0 || n <= 0) return o.steps;
  return std::max(1L, std::lround(o.phase_particle_steps / static_cast<double>(n)));
}

int repeats_of(const BenchOptions& o, std::size_t si) {
  return o.repeats_per_size.empty() ? o.repeats : o.repeats_per_size.at(si);
}

int replays_for(const BenchOptions& o, long n, std::size_t si) {
  if (o.replay_particle_steps <= 0.0 || n <= 0) return 1;
  const double window = static_cast<double>(n) * static_cast<double>(timed_steps_for(o, n)) * repeats_of(o, si);
  return static_cast<int>(std::max(1L, std::lround(o.replay_particle_steps / window)));
}

BenchOptions parse_bench_options(int argc, char** argv) {
  BenchOptions o;
  CLI::App app(kDescription, "centrec_bench_film");
  app.get_formatter()->column_width(30);
  std::vector<double> sizes(o.sizes.begin(), o.sizes.end()), threads(o.threads.begin(), o.threads.end()),
      repeats_per_size;
  double steps = static_cast<double>(o.steps), settle = static_cast<double>(o.settle_steps),
         repeats = o.repeats, facets = o.stl_facets;
  auto list = [&](const char* name, std::vector<double>& v, const char* what) {
    app.add_option(name, v, what)
        ->delimiter(',')
        ->check(cli::positive_number())
        ->expected(1, 1 << 20)
        ->type_name("N,N,..");
  };
  auto number = [&](const char* name, double& v, const char* what) {
    app.add_option(name, v, what)->check(cli::positive_number())->type_name("X");
  };
  list("--sizes", sizes, "target particle counts (default 10000,50000,200000)");
  list("--threads", threads, "centrec OpenMP threads = LIGGGHTS / LAMMPS MPI ranks (default 1,2)");
  number("--steps", steps, "steps per timed phase (default 1000)");
  number("--phase-particle-steps", o.phase_particle_steps,
         "every size's timed phase does P particle-steps: steps = round(P / N), overrides --steps "
         "(equal work, equal duration per phase)");
  number("--replay-particle-steps", o.replay_particle_steps,
         "every size times the same window (--repeats phases of --steps after the settle); a film of N "
         "particles replays that window from its settled state round(P / (N x steps x repeats)) times (at "
         "least once), so all sizes do about P timed particle-steps in the same film state");
  number("--settle", settle, "untimed settle steps before timing (default 2000)");
  number("--repeats", repeats, "timed phases per run; the median is reported (default 3)");
  list("--repeats-per-size", repeats_per_size, "one repeat count per size (overrides --repeats)");
  bool no_liggghts = false, no_lammps = false, no_centrec = false;
  app.add_flag("--no-liggghts", no_liggghts, "do not time LIGGGHTS");
  app.add_flag("--no-lammps", no_lammps, "do not time LAMMPS");
  app.add_flag("--no-centrec", no_centrec, "do not time centrec (peer engines only)");
  app.add_flag("--interleave", o.interleave,
               "centrec: settle every size first, then alternate the sizes' timed phases (phase k of each size "
               "in turn), so a slow spell of the machine hits all sizes and does not skew the cost per particle "
               "between them (LIGGGHTS and LAMMPS runs stay one after the other)");
  number("--liggghts-skin", o.liggghts_skin_d, "LIGGGHTS neighbour skin in diameters (default 0.4)");
  number("--lammps-skin", o.lammps_skin_d, "LAMMPS neighbour skin in diameters (default 0.4)");
  number("--centrec-skin", o.centrec_skin_d, "centrec Verlet skin in diameters (default 0.4)");
  number("--stl-facets", facets, "facets around the LIGGGHTS cylinder mesh (default 720)");
  app.add_option("--liggghts", o.liggghts_exe, "LIGGGHTS executable (default liggghts)")->type_name("EXE");
  app.add_option("--lammps", o.lammps_exe, "LAMMPS executable with the GRANULAR package (default lmp)")
      ->type_name("EXE");
  app.add_option("--mpirun", o.mpirun, "MPI launcher (default mpirun)")->type_name("EXE");
  app.add_option("--out", o.out, "output folder: results.csv, results.md, inputs, logs (default bench-film)")
      ->type_name("DIR");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument(std::string(e.what()) + " (see --help)");
  }
  o.sizes = whole<long>(sizes);
  o.threads = whole<int>(threads);
  o.steps = static_cast<long>(steps);
  o.settle_steps = static_cast<long>(settle);
  o.repeats = static_cast<int>(repeats);
  o.repeats_per_size = whole<int>(repeats_per_size);
  o.stl_facets = static_cast<int>(facets);
  o.liggghts = !no_liggghts;
  o.lammps = !no_lammps;
  o.centrec = !no_centrec;
  if (!o.repeats_per_size.empty() && o.repeats_per_size.size() != o.sizes.size())
    throw std::invalid_argument("--repeats-per-size needs one value per size");
  if (o.replay_particle_steps > 0 && o.phase_particle_steps > 0)
    throw std::invalid_argument("--replay-particle-steps and --phase-particle-steps exclude each other (same window "
                                "for every size, or same work per phase)");
  if (!o.liggghts && !o.lammps && !o.centrec)
    throw std::invalid_argument("--no-liggghts, --no-lammps and --no-centrec: nothing to run");
  return o;
}

}  // namespace centrec::bench
