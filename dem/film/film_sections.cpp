#include "film_sections.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace centrec::film {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int bin_of(double v, double lo, double width, int n) {
  const int b = static_cast<int>(std::floor((v - lo) / width));
  return (b < 0 || b >= n) ? -1 : b;
}

// Eqs (4)-(7) on one set of (r, particle index) pairs; returns thickness and the mean vz
// of the n_p innermost particles (the film surface of eq 7).
std::pair<double, double> section_thickness(std::vector<std::pair<double, std::size_t>>& rs,
                                            const FilmThicknessParams& fp, const double* vz,
                                            std::vector<double>& scratch) {
  if (rs.empty()) return {kNaN, kNaN};
  std::sort(rs.begin(), rs.end());
  scratch.resize(rs.size());
  for (std::size_t i = 0; i < rs.size(); ++i) scratch[i] = rs[i].first;
  const FilmThicknessResult r = film_thickness_sorted(scratch.data(), scratch.size(), fp);
  double v = kNaN;
  if (vz) {
    double sum = 0.0;
    for (std::size_t i = 0; i < r.n_surface; ++i) sum += vz[rs[i].second];
    v = sum / static_cast<double>(r.n_surface);
  }
  return {r.thickness, v};
}
}  // namespace

FilmSectionSnapshot sample_film_sections(const ParticleArrays& p, const DrumFrame& frame, const FilmSectionGrid& g) {
  require_arrays(p, "xyzr", "sample_film_sections");
  if (g.axial_sections < 1 || g.tangential_bins < 1)
    throw std::invalid_argument("sample_film_sections: need at least one section and one bin");
  const double z_max = g.z_max < 0.0 ? frame.length : g.z_max;
  if (!(z_max > g.z_min)) throw std::invalid_argument("sample_film_sections: z_max must exceed z_min");
  const int n_ax = g.axial_sections, n_tan = g.tangential_bins;
  const double dz = (z_max - g.z_min) / n_ax, dth = 2.0 * M_PI / n_tan;

  FilmSectionSnapshot s;
  s.axial_sections = n_ax;
  s.tangential_bins = n_tan;
  double d = g.particle_diameter;
  if (d <= 0.0) {  // polydisperse: the mean diameter stands for d in eqs (5) and (7)
    double sum = 0.0;
    for (std::size_t i = 0; i < p.count; ++i) sum += 2.0 * p.radius[i];
    d = p.count ? sum / static_cast<double>(p.count) : kNaN;
  }
  s.particle_diameter = d;
  s.ring_thickness.assign(n_ax, kNaN);
  s.cell_thickness.assign(static_cast<std::size_t>(n_ax) * n_tan, kNaN);
  s.cell_surface_vz.assign(s.cell_thickness.size(), kNaN);
  s.cell_count.assign(s.cell_thickness.size(), 0);
  if (p.count == 0) return s;

  std::vector<std::vector<std::pair<double, std::size_t>>> cells(s.cell_thickness.size());
  for (std::size_t i = 0; i < p.count; ++i) {
    const int a = bin_of(p.z[i], g.z_min, dz, n_ax);
    if (a < 0) continue;
    const int t = std::min(n_tan - 1, static_cast<int>(frame.theta(p.x[i], p.y[i]) / dth));
    cells[static_cast<std::size_t>(a) * n_tan + t].emplace_back(std::hypot(p.x[i], p.y[i]), i);
  }

  FilmThicknessParams fp;
  fp.cavity_diameter = 2.0 * frame.radius;
  fp.section_length = dz;
  fp.particle_diameter = d;
  fp.solid_fraction = g.solid_fraction;
  std::vector<double> scratch;
  std::vector<std::pair<double, std::size_t>> ring;
  for (int a = 0; a < n_ax; ++a) {
    ring.clear();
    fp.arc_fraction = 1.0 / n_tan;
    for (int t = 0; t < n_tan; ++t) {
      auto& c = cells[static_cast<std::size_t>(a) * n_tan + t];
      ring.insert(ring.end(), c.begin(), c.end());
      const std::size_t k = static_cast<std::size_t>(a) * n_tan + t;
      s.cell_count[k] = c.size();
      const auto tv = section_thickness(c, fp, p.vz, scratch);
      s.cell_thickness[k] = tv.first;
      s.cell_surface_vz[k] = tv.second;
    }
    fp.arc_fraction = 1.0;
    s.ring_thickness[a] = section_thickness(ring, fp, nullptr, scratch).first;
  }
  return s;
}

void FilmThicknessAccumulator::add(const FilmSectionSnapshot& s) {
  if (snapshots_ == 0) {
    n_ax_ = s.axial_sections;
    n_tan_ = s.tangential_bins;
    ring_.assign(n_ax_, {});
    cell_.assign(static_cast<std::size_t>(n_ax_) * n_tan_, {});
    vz_.assign(cell_.size(), {});
  } else if (s.axial_sections != n_ax_ || s.tangential_bins != n_tan_) {
    throw std::invalid_argument("FilmThicknessAccumulator: snapshot grid differs from the first one");
  }
  ++snapshots_;
  if (std::isfinite(s.particle_diameter)) d_.add(s.particle_diameter);
  double sum = 0.0;
  int filled = 0;
  for (int a = 0; a < n_ax_; ++a) {
    if (std::isfinite(s.ring_thickness[a])) {
      ring_[a].add(s.ring_thickness[a]);
      sum += s.ring_thickness[a];
      ++filled;
    }
  }
  if (filled) overall_.add(sum / filled);
  for (std::size_t k = 0; k < cell_.size(); ++k) {
    if (std::isfinite(s.cell_thickness[k])) cell_[k].add(s.cell_thickness[k]);
    if (std::isfinite(s.cell_surface_vz[k])) vz_[k].add(s.cell_surface_vz[k]);
  }
}

LengthStat FilmThicknessAccumulator::to_length(const RunningStats& s) const {
  LengthStat l;
  l.samples = s.count();
  l.mean_m = s.mean();
  l.std_m = s.stddev();
  const double d = d_.mean();
  l.mean_d = l.mean_m / d;
  l.std_d = l.std_m / d;
  return l;
}

LengthStat FilmThicknessAccumulator::ring(int a) const { return to_length(ring_.at(a)); }
LengthStat FilmThicknessAccumulator::cell(int a, int t) const {
  return to_length(cell_.at(static_cast<std::size_t>(a) * n_tan_ + t));
}
LengthStat FilmThicknessAccumulator::overall() const { return to_length(overall_); }
const RunningStats& FilmThicknessAccumulator::surface_velocity_cell(int a, int t) const {
  return vz_.at(static_cast<std::size_t>(a) * n_tan_ + t);
}

std::vector<double> FilmThicknessAccumulator::surface_velocity(int axial_lo, int axial_hi) const {
  std::vector<double> v(n_tan_, kNaN);
  for (int t = 0; t < n_tan_; ++t) {
    double sum = 0.0;
    int n = 0;
    for (int a = std::max(0, axial_lo); a < std::min(n_ax_, axial_hi); ++a) {
      const RunningStats& s = vz_[static_cast<std::size_t>(a) * n_tan_ + t];
      if (s.count()) {
        sum += s.mean();
        ++n;
      }
    }
    if (n) v[t] = sum / n;
  }
  return v;
}

void FilmThicknessAccumulator::save(PackedState& out) const {
  out.put(n_ax_);
  out.put(n_tan_);
  out.put(static_cast<double>(snapshots_));
  out.put(d_);
  out.put(overall_);
  out.put_all(ring_);
  out.put_all(cell_);
  out.put_all(vz_);
}

void FilmThicknessAccumulator::load(StateReader& in) {
  n_ax_ = static_cast<int>(in.count());
  n_tan_ = static_cast<int>(in.count());
  snapshots_ = in.count();
  d_ = in.stats();
  overall_ = in.stats();
  in.get_all(ring_);
  in.get_all(cell_);
  in.get_all(vz_);
  if (ring_.size() != static_cast<std::size_t>(n_ax_) || cell_.size() != static_cast<std::size_t>(n_ax_) * n_tan_ ||
      vz_.size() != cell_.size())
    throw std::invalid_argument("FilmThicknessAccumulator: saved state is inconsistent");
}

}  // namespace centrec::film
