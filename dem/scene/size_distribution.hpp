#pragma once
// Particle sizes drawn from the scene's distribution (mono, uniform, truncated normal).
#include <random>
#include <string>

#include "dem/scene/scene_config.hpp"

namespace centrec::dem::scene {

class SizeSampler {
 public:
  SizeSampler(const ParticleSpec& spec, std::uint64_t seed);
  double next_diameter();
  double max_diameter() const;
  double min_diameter() const;  // the distribution's smallest (normal: cut at 3 sigma)
  // The generator's state as text (std::mt19937_64 stream format), for checkpoints.
  std::string rng_state() const;
  void set_rng_state(const std::string& text);  // throws std::invalid_argument if unreadable

 private:
  ParticleSpec spec_;
  std::mt19937_64 rng_;
};

}  // namespace centrec::dem::scene
