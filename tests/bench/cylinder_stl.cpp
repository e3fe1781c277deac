#include "tests/bench/cylinder_stl.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace centrec::bench {
namespace {

struct P3 {
  double x, y, z;
};

void facet(std::FILE* f, P3 a, P3 b, P3 c) {
  // Normal from the vertex order (right-hand rule), as LIGGGHTS derives it.
  const P3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
  P3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  const double l = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  std::fprintf(f, " facet normal %.9g %.9g %.9g\n  outer loop\n", n.x / l, n.y / l, n.z / l);
  for (const P3& p : {a, b, c}) std::fprintf(f, "   vertex %.17g %.17g %.17g\n", p.x, p.y, p.z);
  std::fprintf(f, "  endloop\n endfacet\n");
}

}  // namespace

long write_cylinder_stl(const std::string& path, double radius, double length, int around, int axial) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "solid drum\n");
  long n = 0;
  for (int i = 0; i < around; ++i) {
    const double t0 = 2.0 * M_PI * i / around, t1 = 2.0 * M_PI * (i + 1) / around;
    for (int s = 0; s < axial; ++s) {
      const double z0 = length * s / axial, z1 = length * (s + 1) / axial;
      const P3 a{radius * std::cos(t0), radius * std::sin(t0), z0};
      const P3 b{radius * std::cos(t1), radius * std::sin(t1), z0};
      const P3 c{radius * std::cos(t1), radius * std::sin(t1), z1};
      const P3 d{radius * std::cos(t0), radius * std::sin(t0), z1};
      // Order a-c-b / a-d-c makes the normal point towards the axis.
      facet(f, a, c, b);
      facet(f, a, d, c);
      n += 2;
    }
  }
  std::fprintf(f, "endsolid drum\n");
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
  return n;
}

}  // namespace centrec::bench
