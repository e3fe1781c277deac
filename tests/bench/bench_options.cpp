#include "tests/bench/bench_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace centrec::bench {
namespace {

const char* kHelp =
    "centrec_bench_film: DEM speed of centrec vs LIGGGHTS 3.8 on a settled particle film in the\n"
    "D12 drum. Both engines start from the same lattice file, settle, then run\n"
    "timed phases; the median phase gives particle-steps/s.\n\n"
    "  --sizes N,N,..       target particle counts (default 10000,50000,200000)\n"
    "  --threads T,T,..     centrec OpenMP threads = LIGGGHTS MPI ranks (default 1,2)\n"
    "  --steps S            steps per timed phase (default 1000)\n"
    "  --phase-particle-steps P  every size's timed phase does P particle-steps: steps =\n"
    "                       round(P / N), overrides --steps (equal work, equal duration per phase)\n"
    "  --replay-particle-steps P  every size times the same window (--repeats phases of --steps\n"
    "                       after the settle); a film of N particles replays that window from its\n"
    "                       settled state round(P / (N x steps x repeats)) times (at least once),\n"
    "                       so all sizes do about P timed particle-steps in the same film state\n"
    "  --settle S           untimed settle steps before timing (default 2000)\n"
    "  --repeats R          timed phases per run; the median is reported (default 3)\n"
    "  --repeats-per-size R,R,..  one repeat count per size (overrides --repeats)\n"
    "  --no-liggghts        time centrec only\n"
    "  --no-centrec         time LIGGGHTS only\n"
    "  --interleave         centrec: settle every size first, then alternate the sizes' timed\n"
    "                       phases (phase k of each size in turn), so a slow spell of the machine\n"
    "                       hits all sizes and does not skew the cost per particle between them\n"
    "                       (LIGGGHTS runs stay one after the other)\n"
    "  --liggghts-skin F    LIGGGHTS neighbour skin in diameters (default 0.4)\n"
    "  --centrec-skin F     centrec Verlet skin in diameters (default 0.4)\n"
    "  --stl-facets K       facets around the LIGGGHTS cylinder mesh (default 720)\n"
    "  --liggghts EXE       LIGGGHTS executable (default liggghts)\n"
    "  --mpirun EXE         MPI launcher (default mpirun)\n"
    "  --out DIR            output folder: results.csv, results.md, inputs, logs (default bench-film)\n";

template <class T>
std::vector<T> parse_list(const std::string& opt, const std::string& s) {
  std::vector<T> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::istringstream is(item);
    double v;
    if (!(is >> v) || v <= 0) throw std::invalid_argument(opt + ": bad value '" + item + "' (positive numbers)");
    out.push_back(static_cast<T>(v));
  }
  if (out.empty()) throw std::invalid_argument(opt + ": empty list");
  return out;
}

double parse_positive(const std::string& opt, const std::string& s) {
  return parse_list<double>(opt, s).at(0);
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
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      std::exit(0);
    } else if (a == "--sizes") o.sizes = parse_list<long>(a, value());
    else if (a == "--threads") o.threads = parse_list<int>(a, value());
    else if (a == "--steps") o.steps = static_cast<long>(parse_positive(a, value()));
    else if (a == "--phase-particle-steps") o.phase_particle_steps = parse_positive(a, value());
    else if (a == "--replay-particle-steps") o.replay_particle_steps = parse_positive(a, value());
    else if (a == "--settle") o.settle_steps = static_cast<long>(parse_positive(a, value()));
    else if (a == "--repeats") o.repeats = static_cast<int>(parse_positive(a, value()));
    else if (a == "--repeats-per-size") o.repeats_per_size = parse_list<int>(a, value());
    else if (a == "--no-liggghts") o.liggghts = false;
    else if (a == "--no-centrec") o.centrec = false;
    else if (a == "--interleave") o.interleave = true;
    else if (a == "--liggghts-skin") o.liggghts_skin_d = parse_positive(a, value());
    else if (a == "--centrec-skin") o.centrec_skin_d = parse_positive(a, value());
    else if (a == "--stl-facets") o.stl_facets = static_cast<int>(parse_positive(a, value()));
    else if (a == "--liggghts") o.liggghts_exe = value();
    else if (a == "--mpirun") o.mpirun = value();
    else if (a == "--out") o.out = value();
    else throw std::invalid_argument("unknown option " + a + " (see --help)");
  }
  if (!o.repeats_per_size.empty() && o.repeats_per_size.size() != o.sizes.size())
    throw std::invalid_argument("--repeats-per-size needs one value per size");
  if (o.replay_particle_steps > 0 && o.phase_particle_steps > 0)
    throw std::invalid_argument("--replay-particle-steps and --phase-particle-steps exclude each other (same window "
                                "for every size, or same work per phase)");
  if (!o.liggghts && !o.centrec) throw std::invalid_argument("--no-liggghts and --no-centrec: nothing to run");
  return o;
}

}  // namespace centrec::bench
