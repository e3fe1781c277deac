#include "bench/engine_result.hpp"

#include <algorithm>

namespace centrec::bench {

double EngineResult::median_seconds() const {
  if (seconds.empty()) return 0.0;
  std::vector<double> s = seconds;
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

double EngineResult::particle_steps_per_second() const {
  const double t = median_seconds();
  return t > 0 ? static_cast<double>(particles) * static_cast<double>(steps) / t : 0.0;
}

}  // namespace centrec::bench
