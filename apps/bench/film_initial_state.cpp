#include "bench/film_initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace centrec::bench {
namespace {

// Spacings with a 1 % gap: the lattice starts without overlaps, so the first steps
// produce no violent repulsion, and the settle phase only has to close the gaps.
constexpr double kGap = 1.01;

double row_spacing(const FilmCase& c) { return kGap * c.diameter; }
// Adjacent layers are shifted half a row along z, so their centres are at least
// sqrt((a/2)^2 + h^2) apart whatever their angular offset: pick h for >= 1.01 d.
double layer_spacing(const FilmCase& c) {
  const double a = row_spacing(c), d = c.diameter;
  return kGap * std::sqrt(d * d - 0.25 * a * a);
}
double ring_radius(const FilmCase& c, int layer) {
  // 4 microns off the wall (more than the jitter can move a centre radially, sqrt(2) x
  // 2.4 um): no initial wall overlap, and the first wall contacts form in the first steps.
  return c.drum_radius - c.radius() - 4e-6 - layer * layer_spacing(c);
}
// Particles on a ring of radius r with chord (centre distance) >= a.
long ring_count(double r, double a) { return static_cast<long>(std::floor(M_PI / std::asin(0.5 * a / r))); }

// Deterministic jitter in [-1, 1) from the particle index and coordinate (splitmix64): the
// same on every platform, and it breaks the lattice's exact symmetry under a shift by one
// row, which would otherwise keep every row's motion identical until round-off grows.
double jitter(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
}
// Jitter amplitude per coordinate: 0.2 % of d, so two neighbours approach by at most
// 2 sqrt(3) x 0.2 % d = 0.7 % d, less than the lattice's 1 % gap.
constexpr double kJitter = 0.002;

}  // namespace

long film_particles_per_row(const FilmCase& c) {
  long n = 0;
  for (int k = 0; k < c.layers; ++k) n += ring_count(ring_radius(c, k), row_spacing(c));
  return n;
}

FilmState make_film_lattice(const FilmCase& c, long target_n) {
  const double a = row_spacing(c);
  const long per_row = film_particles_per_row(c);
  // At least 6 rows: centrec's periodic cell grid needs the period >= 3 cells of
  // d + skin (skin up to 1 d), and each half of the 2-rank LIGGGHTS split along z must be
  // longer than its neighbour cut-off.
  const long rows = std::max(6L, std::lround(static_cast<double>(target_n) / per_row));
  FilmState s;
  s.length = rows * a;
  s.diameter = c.diameter;
  s.particles.reserve(static_cast<std::size_t>(rows * per_row));
  const double W = c.omega();
  for (int k = 0; k < c.layers; ++k) {
    const double r = ring_radius(c, k);
    const long n = ring_count(r, a);
    const double shift = 0.5 * (k % 2);
    for (long iz = 0; iz < rows; ++iz) {
      const double z = (iz + 0.25 + shift) * a;
      for (long j = 0; j < n; ++j) {
        const double th = 2.0 * M_PI * (j + shift) / n;
        ParticleState p{};
        const std::uint64_t id = 3 * s.particles.size();
        const double amp = kJitter * c.diameter;
        p.x[0] = r * std::cos(th) + amp * jitter(id);
        p.x[1] = r * std::sin(th) + amp * jitter(id + 1);
        p.x[2] = z + amp * jitter(id + 2);
        // Rigid co-rotation with the drum: v = omega z x r, spin = omega z.
        p.v[0] = -W * p.x[1];
        p.v[1] = W * p.x[0];
        p.w[2] = W;
        s.particles.push_back(p);
      }
    }
  }
  return s;
}

void write_film_state(const std::string& path, const FilmState& s) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "# centrec benchmark film initial state (SI units)\n");
  std::fprintf(f, "# length %.17g\n# diameter %.17g\n# count %zu\n", s.length, s.diameter, s.particles.size());
  std::fprintf(f, "# x y z vx vy vz wx wy wz\n");
  for (const auto& p : s.particles)
    std::fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.x[0], p.x[1], p.x[2], p.v[0],
                 p.v[1], p.v[2], p.w[0], p.w[1], p.w[2]);
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

FilmState read_film_state(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  FilmState s;
  long count = -1;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      std::istringstream h(line.substr(1));
      std::string key;
      h >> key;
      if (key == "length") h >> s.length;
      else if (key == "diameter") h >> s.diameter;
      else if (key == "count") h >> count;
      continue;
    }
    std::istringstream l(line);
    ParticleState p{};
    for (double* q : {p.x, p.v, p.w})
      for (int i = 0; i < 3; ++i) l >> q[i];
    if (!l) throw std::runtime_error(path + ": bad particle line: " + line);
    s.particles.push_back(p);
  }
  if (count != static_cast<long>(s.particles.size()) || s.length <= 0 || s.diameter <= 0)
    throw std::runtime_error(path + ": header (length, diameter, count) missing or count mismatch");
  return s;
}

}  // namespace centrec::bench
