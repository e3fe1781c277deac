#include "velocity_profile.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::film {

std::vector<ArcSection> paper_arc_sections() {
  std::vector<ArcSection> s;
  for (double z : {0.3, 0.5, 0.7})
    for (double deg : {45.0, 90.0, 135.0}) s.push_back({deg * M_PI / 180.0, z});
  return s;
}

VelocityProfileSampler::VelocityProfileSampler(const DrumFrame& frame, VelocityProfileConfig config)
    : frame_(frame), config_(std::move(config)) {
  config_.bins.check("VelocityProfileSampler");
  if (!(config_.arc_half_width > 0.0 && config_.arc_half_width <= M_PI) || !(config_.axial_half_length > 0.0))
    throw std::invalid_argument("VelocityProfileSampler: arc half-width in (0, pi] and axial half-length > 0");
  if (!(frame_.length > 0.0)) throw std::invalid_argument("VelocityProfileSampler: drum length must be positive");
  profiles_.assign(config_.sections.size(), PeriodProfile(config_.bins.count));
}

void VelocityProfileSampler::add_snapshot(const ParticleArrays& p) {
  require_arrays(p, "xyzv", "VelocityProfileSampler");
  const double half_z = config_.axial_half_length * frame_.length;
  for (std::size_t i = 0; i < p.count; ++i) {
    const int k = config_.bins.index(frame_.wall_distance(p.x[i], p.y[i]));
    if (k < 0) continue;
    const double th = frame_.theta(p.x[i], p.y[i]);
    for (std::size_t s = 0; s < config_.sections.size(); ++s) {
      const ArcSection& a = config_.sections[s];
      if (std::fabs(p.z[i] - a.z_over_length * frame_.length) > half_z) continue;
      // Angular distance on the circle, in [0, pi].
      const double dth = std::fabs(wrap_angle(th - a.theta + M_PI) - M_PI);
      if (dth > config_.arc_half_width) continue;
      profiles_[s].add(k, p.vz[i]);
    }
  }
}

void VelocityProfileSampler::end_period() {
  for (auto& pr : profiles_) pr.end_period();
  ++periods_;
}

std::vector<ProfileBin> VelocityProfileSampler::profile(int section) const {
  return profiles_.at(section).all();
}

void VelocityProfileSampler::save(PackedState& out) const {
  out.put(static_cast<double>(periods_));
  for (const auto& pr : profiles_) pr.save(out);
}

void VelocityProfileSampler::load(StateReader& in) {
  periods_ = in.count();
  for (auto& pr : profiles_) pr.load(in);
}

}  // namespace centrec::film
