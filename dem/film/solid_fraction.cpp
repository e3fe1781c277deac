#include "solid_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dem/film/sphere_shell_volume.hpp"

namespace centrec::film {

SolidFractionSampler::SolidFractionSampler(const DrumFrame& frame, SolidFractionConfig config)
    : frame_(frame), config_(std::move(config)) {
  config_.bins.check("SolidFractionSampler");
  if (config_.zone_of_bin.empty()) throw std::invalid_argument("SolidFractionSampler: no tangential bins");
  if (config_.z_max < 0.0) config_.z_max = frame_.length;
  if (!(config_.z_max > config_.z_min)) throw std::invalid_argument("SolidFractionSampler: z_max must exceed z_min");
  if (config_.bins.count * config_.bins.width_m() > frame_.radius)
    throw std::invalid_argument("SolidFractionSampler: bins reach past the drum axis");
  for (int z : config_.zone_of_bin)
    if (z < 0) throw std::invalid_argument("SolidFractionSampler: negative zone index");
  n_zones_ = *std::max_element(config_.zone_of_bin.begin(), config_.zone_of_bin.end()) + 1;
  zone_angle_.assign(n_zones_, 0.0);
  const double dth = 2.0 * M_PI / config_.zone_of_bin.size();
  for (int z : config_.zone_of_bin) zone_angle_[z] += dth;
  profiles_.assign(n_zones_, PeriodProfile(config_.bins.count));
}

void SolidFractionSampler::add_snapshot(const ParticleArrays& p) {
  require_arrays(p, "xyzr", "SolidFractionSampler");
  const WallDistanceBins& b = config_.bins;
  const int n_tan = static_cast<int>(config_.zone_of_bin.size());
  const double R = frame_.radius;
  std::vector<double> vol(static_cast<std::size_t>(n_zones_) * b.count, 0.0);
  for (std::size_t i = 0; i < p.count; ++i) {
    if (p.z[i] < config_.z_min || p.z[i] >= config_.z_max) continue;
    const double c = std::hypot(p.x[i], p.y[i]);
    const double a = p.radius[i];
    const int t = std::min(n_tan - 1, static_cast<int>(frame_.theta(p.x[i], p.y[i]) / (2.0 * M_PI) * n_tan));
    const int zone = config_.zone_of_bin[t];
    // Only the bins the sphere reaches: wall distances R - c - a .. R - c + a.
    const int k_lo = std::max(0, static_cast<int>(std::floor((R - c - a) / b.width_m())));
    const int k_hi = std::min(b.count - 1, static_cast<int>(std::floor((R - c + a) / b.width_m())));
    // Bin k is the shell R - upper(k) < r <= R - lower(k); neighbours share a boundary,
    // so each cylinder volume is computed once.
    double v_outer = sphere_in_cylinder_volume(R - b.lower_m(k_lo), a, c);
    for (int k = k_lo; k <= k_hi; ++k) {
      const double v_inner = sphere_in_cylinder_volume(R - b.upper_m(k), a, c);
      vol[static_cast<std::size_t>(zone) * b.count + k] += v_outer - v_inner;
      v_outer = v_inner;
    }
  }
  const double lz = config_.z_max - config_.z_min;
  for (int z = 0; z < n_zones_; ++z) {
    if (zone_angle_[z] <= 0.0) continue;
    for (int k = 0; k < b.count; ++k) {
      const double r_out = R - b.lower_m(k), r_in = R - b.upper_m(k);
      const double shell = 0.5 * zone_angle_[z] * (r_out * r_out - r_in * r_in) * lz;
      profiles_[z].add(k, vol[static_cast<std::size_t>(z) * b.count + k] / shell);
    }
  }
}

void SolidFractionSampler::end_period() {
  for (auto& pr : profiles_) pr.end_period();
}

std::vector<ProfileBin> SolidFractionSampler::profile(int zone) const {
  return profiles_.at(zone).all();
}

void SolidFractionSampler::save(PackedState& out) const {
  for (const auto& pr : profiles_) pr.save(out);
}

void SolidFractionSampler::load(StateReader& in) {
  for (auto& pr : profiles_) pr.load(in);
}

}  // namespace centrec::film
