#include "synthetic_films.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace centrec::film::test {

DrumFrame paper_view_frame(double R, double L) {
  DrumFrame f;
  f.radius = R;
  f.length = L;
  return f;
}

FilmSectionGrid section_grid(int axial_sections, int tangential_bins, double d) {
  FilmSectionGrid g;
  g.axial_sections = axial_sections;
  g.tangential_bins = tangential_bins;
  g.particle_diameter = d;
  return g;
}

void Particles::add(double px, double py, double pz, double r) {
  x.push_back(px);
  y.push_back(py);
  z.push_back(pz);
  vx.push_back(0.0);
  vy.push_back(0.0);
  vz.push_back(0.0);
  radius.push_back(r);
  id.push_back(static_cast<std::int64_t>(id.size()));
}

Particles layered_lattice(double R, double length, double d, int layers, double h, double a_theta, double a_z,
                          bool stagger) {
  Particles p;
  const int nz = static_cast<int>(std::floor(length / a_z + 1e-9));
  // One angular count for all layers, set by the innermost (shortest) ring so its chord
  // 2 r sin(pi / n) >= a_theta; staggered layers then sit over the hollows below.
  const double r_in = R - 0.5 * d - (layers - 1) * h;
  const int nt = static_cast<int>(std::floor(M_PI / std::asin(a_theta / (2.0 * r_in))));
  for (int k = 0; k < layers; ++k) {
    const double r = R - 0.5 * d - k * h;
    const double shift = (stagger && (k % 2)) ? 0.5 : 0.0;
    for (int j = 0; j < nt; ++j) {
      const double th = (j + shift) * 2.0 * M_PI / nt;
      for (int m = 0; m < nz; ++m) p.add(r * std::cos(th), r * std::sin(th), (m + 0.5 + shift) * length / nz, 0.5 * d);
    }
  }
  return p;
}

namespace {
double gap_z(double dz, double length) { return dz - length * std::round(dz / length); }
}  // namespace

Particles random_packing(double R, double t, double length, double d, double phi, std::mt19937_64& rng) {
  const double v_p = M_PI * d * d * d / 6.0;
  const std::size_t n = static_cast<std::size_t>(std::lround(phi * M_PI * (R * R - (R - t) * (R - t)) * length / v_p));
  const double r_lo = R - t + 0.5 * d, r_hi = R - 0.5 * d;  // where centres may lie
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Particles p;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(r_lo * r_lo + u01(rng) * (r_hi * r_hi - r_lo * r_lo));  // uniform in area
    const double th = 2.0 * M_PI * u01(rng);
    p.add(r * std::cos(th), r * std::sin(th), length * u01(rng), 0.5 * d);
  }
  // Overlap relaxation: push overlapping pairs apart, keep centres between the walls;
  // below jamming (~0.64) this ends overlap-free.
  const int ng = static_cast<int>(std::ceil(2.0 * R / d)) + 2;
  const int nz = std::max(3, static_cast<int>(std::floor(length / d)));
  std::vector<int> head(static_cast<std::size_t>(ng) * ng * nz), next(n);
  auto cell = [&](int i, int j, int k) { return (static_cast<std::size_t>(i) * ng + j) * nz + k; };
  std::vector<int> ci(n), cj(n), ck(n);
  for (int it = 0; it < 20000; ++it) {
    std::fill(head.begin(), head.end(), -1);
    for (std::size_t a = 0; a < n; ++a) {
      ci[a] = static_cast<int>((p.x[a] + R) / d) + 1;
      cj[a] = static_cast<int>((p.y[a] + R) / d) + 1;
      ck[a] = std::min(nz - 1, static_cast<int>(p.z[a] / length * nz));
      const std::size_t c = cell(ci[a], cj[a], ck[a]);
      next[a] = head[c];
      head[c] = static_cast<int>(a);
    }
    double worst = 0.0;
    // Gauss-Seidel: each overlapping pair is separated at once (a little past contact),
    // the walls are enforced per move; far faster than simultaneous (Jacobi) updates.
    auto wall = [&](std::size_t a) {
      const double r = std::hypot(p.x[a], p.y[a]), rc = std::clamp(r, r_lo, r_hi);
      p.x[a] *= rc / r;
      p.y[a] *= rc / r;
      p.z[a] -= length * std::floor(p.z[a] / length);
    };
    for (std::size_t a = 0; a < n; ++a)
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj)
          for (int dk = -1; dk <= 1; ++dk)
            for (int b = head[cell(ci[a] + di, cj[a] + dj, (ck[a] + dk + nz) % nz)]; b >= 0; b = next[b]) {
              if (static_cast<std::size_t>(b) <= a) continue;
              const double dx = p.x[a] - p.x[b], dy = p.y[a] - p.y[b], dz = gap_z(p.z[a] - p.z[b], length);
              const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
              const double ov = d - dist;
              if (ov <= 0.0 || dist == 0.0) continue;
              worst = std::max(worst, ov);
              const double f = 0.5 * (ov + 1e-4 * d) / dist;
              p.x[a] += f * dx, p.y[a] += f * dy, p.z[a] += f * dz;
              p.x[b] -= f * dx, p.y[b] -= f * dy, p.z[b] -= f * dz;
              wall(a);
              wall(static_cast<std::size_t>(b));
            }
    if (worst == 0.0) return p;  // a full pass without a single overlap (or move)
  }
  throw std::runtime_error("random_packing: overlaps did not relax (solid fraction too high?)");
}

double min_gap(const Particles& p, double length) {
  // Sort by z and compare neighbours within a window: O(n * window).
  const double dmax = 2.0 * *std::max_element(p.radius.begin(), p.radius.end());
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.z[a] < p.z[b]; });
  double g = std::numeric_limits<double>::infinity();
  const std::size_t n = order.size();
  for (std::size_t ii = 0; ii < n; ++ii) {
    for (std::size_t s = 1; s < n; ++s) {
      const std::size_t a = order[ii], b = order[(ii + s) % n];
      double dz = p.z[b] - p.z[a];
      if (ii + s >= n) dz += length;
      if (dz > dmax) break;
      const double dist = std::sqrt((p.x[a] - p.x[b]) * (p.x[a] - p.x[b]) + (p.y[a] - p.y[b]) * (p.y[a] - p.y[b]) +
                                    gap_z(dz, length) * gap_z(dz, length));
      g = std::min(g, dist - p.radius[a] - p.radius[b]);
    }
  }
  return g;
}

}  // namespace centrec::film::test
