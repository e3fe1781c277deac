#include "liggghts/liggghts_stl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/atomic_write.hpp"

namespace centrec::liggghts {
namespace {

struct P3 {
  double x, y, z;
};

void facet(std::ostream& out, P3 a, P3 b, P3 c) {
  // Normal from the vertex order (right-hand rule), as LIGGGHTS derives it.
  const P3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
  const P3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  const double l = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  char line[160];
  std::snprintf(line, sizeof line, " facet normal %.9g %.9g %.9g\n  outer loop\n", n.x / l, n.y / l, n.z / l);
  out << line;
  for (const P3& p : {a, b, c}) {
    std::snprintf(line, sizeof line, "   vertex %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out << line;
  }
  out << "  endloop\n endfacet\n";
}

P3 on_circle(double r, double theta, double z) { return {r * std::cos(theta), r * std::sin(theta), z}; }

}  // namespace

long write_cylinder_facets(std::ostream& out, double radius, double z0, double z1, int around, int axial) {
  long n = 0;
  for (int i = 0; i < around; ++i) {
    const double t0 = 2.0 * M_PI * i / around, t1 = 2.0 * M_PI * (i + 1) / around;
    for (int s = 0; s < axial; ++s) {
      const double za = z0 + (z1 - z0) * s / axial, zb = z0 + (z1 - z0) * (s + 1) / axial;
      const P3 a = on_circle(radius, t0, za), b = on_circle(radius, t1, za);
      const P3 c = on_circle(radius, t1, zb), d = on_circle(radius, t0, zb);
      // Order a-c-b / a-d-c makes the normal point towards the axis.
      facet(out, a, c, b);
      facet(out, a, d, c);
      n += 2;
    }
  }
  return n;
}

long write_annulus_facets(std::ostream& out, double z, double r_in, double r_out, int around, bool normal_up) {
  long n = 0;
  for (int i = 0; i < around; ++i) {
    const double t0 = 2.0 * M_PI * i / around, t1 = 2.0 * M_PI * (i + 1) / around;
    const P3 a = on_circle(r_out, t0, z), b = on_circle(r_out, t1, z);
    // Counter-clockwise seen from +z gives a +z normal.
    auto tri = [&](P3 p, P3 q, P3 r) { normal_up ? facet(out, p, q, r) : facet(out, p, r, q); };
    if (r_in <= 0.0) {
      tri(P3{0.0, 0.0, z}, a, b);
      n += 1;
    } else {
      const P3 c = on_circle(r_in, t1, z), d = on_circle(r_in, t0, z);
      tri(d, a, b);
      tri(d, b, c);
      n += 2;
    }
  }
  return n;
}

double cylinder_curvature_deg(double radius, double length, int around, int axial) {
  const double turn = 360.0 / around;
  const double width = 2.0 * radius * std::sin(M_PI / around), height = length / axial;
  const double smallest = std::atan(std::min(width, height) / std::max(width, height)) * 180.0 / M_PI;
  if (!(turn < smallest)) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "cylinder mesh: facet columns turn by %.3g deg but a triangle's smallest angle is %.3g deg; "
                  "LIGGGHTS cannot carry contact history across them (shorter facets needed)",
                  turn, smallest);
    throw std::invalid_argument(msg);
  }
  return 0.5 * (turn + smallest);
}

int facets_along(double radius, double length, int around) {
  return std::max(1, static_cast<int>(std::ceil(length / (10.0 * 2.0 * M_PI * radius / around))));
}

int facets_around(double radius, double sagitta) {
  const double c = 1.0 - std::min(0.5, sagitta / radius);
  return std::max(24, static_cast<int>(std::ceil(M_PI / std::acos(c))));
}

long write_cylinder_stl(const std::string& path, double radius, double length, int around, int axial) {
  std::ostringstream out;
  out << "solid drum\n";
  const long n = write_cylinder_facets(out, radius, 0.0, length, around, axial);
  out << "endsolid drum\n";
  io::write_text_atomically(path, out.str());
  return n;
}

}  // namespace centrec::liggghts
