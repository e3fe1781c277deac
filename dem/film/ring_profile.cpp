#include "ring_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dem/film/sphere_shell_volume.hpp"

namespace centrec::film {

RingProfileSampler::RingProfileSampler(const DrumFrame& frame, RingProfileConfig config)
    : frame_(frame), config_(std::move(config)) {
  config_.bins.check("RingProfileSampler");
  if (config_.sections < 1) throw std::invalid_argument("RingProfileSampler: needs at least one axial section");
  if (config_.z_max < 0.0) config_.z_max = frame_.length;
  if (!(config_.z_max > config_.z_min)) throw std::invalid_argument("RingProfileSampler: z_max must exceed z_min");
  if (config_.bins.count * config_.bins.width_m() > frame_.radius)
    throw std::invalid_argument("RingProfileSampler: bins reach past the drum axis");
  phi_.assign(static_cast<std::size_t>(config_.sections), PeriodProfile(config_.bins.count));
  flux_ = phi_;
}

double RingProfileSampler::section_centre(int a) const {
  return config_.z_min + (a + 0.5) * (config_.z_max - config_.z_min) / config_.sections;
}

void RingProfileSampler::add_snapshot(const ParticleArrays& p) {
  require_arrays(p, "xyzvr", "RingProfileSampler");
  const WallDistanceBins& b = config_.bins;
  const int ns = config_.sections, nb = b.count;
  const double R = frame_.radius, z0 = config_.z_min, lz = (config_.z_max - z0) / ns;
  std::vector<double> vol(static_cast<std::size_t>(ns) * nb, 0.0), mom = vol;
  for (std::size_t i = 0; i < p.count; ++i) {
    const double s = std::floor((p.z[i] - z0) / lz);
    if (s < 0.0 || s >= ns) continue;
    const std::size_t row = static_cast<std::size_t>(s) * nb;
    const double c = std::hypot(p.x[i], p.y[i]), r = p.radius[i];
    const int k_lo = std::max(0, static_cast<int>(std::floor((R - c - r) / b.width_m())));
    const int k_hi = std::min(nb - 1, static_cast<int>(std::floor((R - c + r) / b.width_m())));
    double v_outer = sphere_in_cylinder_volume(R - b.lower_m(k_lo), r, c);
    for (int k = k_lo; k <= k_hi; ++k) {
      const double v_inner = sphere_in_cylinder_volume(R - b.upper_m(k), r, c);
      vol[row + k] += v_outer - v_inner;
      mom[row + k] += (v_outer - v_inner) * p.vz[i];
      v_outer = v_inner;
    }
  }
  for (int a = 0; a < ns; ++a)
    for (int k = 0; k < nb; ++k) {
      const double r_out = R - b.lower_m(k), r_in = R - b.upper_m(k);
      const double shell = M_PI * (r_out * r_out - r_in * r_in) * lz;
      const std::size_t at = static_cast<std::size_t>(a) * nb + k;
      phi_[a].add(k, vol[at] / shell);
      flux_[a].add(k, mom[at] / shell);
    }
}

void RingProfileSampler::end_period() {
  for (auto& p : phi_) p.end_period();
  for (auto& p : flux_) p.end_period();
}

void RingProfileSampler::save(PackedState& out) const {
  for (const auto& p : phi_) p.save(out);
  for (const auto& p : flux_) p.save(out);
}

void RingProfileSampler::load(StateReader& in) {
  for (auto& p : phi_) p.load(in);
  for (auto& p : flux_) p.load(in);
}

}  // namespace centrec::film
