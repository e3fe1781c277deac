#include "dem/scene/size_distribution.hpp"

#include <algorithm>

#include "dem/scene/rng_state.hpp"
#include <stdexcept>

namespace centrec::dem::scene {

SizeSampler::SizeSampler(const ParticleSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {
  if (!(spec.diameter > 0.0)) throw std::invalid_argument("particle diameter must be positive");
  if (spec.relative_spread < 0.0 || spec.relative_spread >= 0.3)
    throw std::invalid_argument("particle relative_spread must be in [0, 0.3)");
}

std::string SizeSampler::rng_state() const { return rng_text(rng_); }

void SizeSampler::set_rng_state(const std::string& text) { read_rng_text(text, rng_, "size sampler"); }

double SizeSampler::max_diameter() const {
  switch (spec_.distribution) {
    case SizeDistribution::mono: return spec_.diameter;
    case SizeDistribution::uniform: return spec_.diameter * (1.0 + spec_.relative_spread);
    case SizeDistribution::normal: return spec_.diameter * (1.0 + 3.0 * spec_.relative_spread);
  }
  return spec_.diameter;
}

double SizeSampler::min_diameter() const {
  switch (spec_.distribution) {
    case SizeDistribution::mono: return spec_.diameter;
    case SizeDistribution::uniform: return spec_.diameter * (1.0 - spec_.relative_spread);
    case SizeDistribution::normal: return spec_.diameter * (1.0 - 3.0 * spec_.relative_spread);
  }
  return spec_.diameter;
}

double SizeSampler::next_diameter() {
  const double d = spec_.diameter, s = spec_.relative_spread;
  switch (spec_.distribution) {
    case SizeDistribution::mono: return d;
    case SizeDistribution::uniform: {
      std::uniform_real_distribution<double> u(d * (1.0 - s), d * (1.0 + s));
      return u(rng_);
    }
    case SizeDistribution::normal: {
      // Truncated at 3 sigma so no sphere is near zero size or far above the cell size.
      std::normal_distribution<double> n(d, d * s);
      for (;;) {
        const double x = n(rng_);
        if (std::abs(x - d) <= 3.0 * d * s) return x;
      }
    }
  }
  return d;
}

}  // namespace centrec::dem::scene
