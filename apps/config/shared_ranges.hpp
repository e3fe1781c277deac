#pragma once
// The ranges of the case values that more than one place reads: the operating point (receiver,
// sweep grid, the --speed-rpm and --mass-flow flags, cli/case_overrides.cpp) and the run values
// the flags --threads, --duration and --seed set (their keys' readers check them, so a flag
// accepts exactly what the key accepts).
#include "config/strict_yaml.hpp"

namespace centrec::config::shared_ranges {

inline Range speed_rpm() { return Range::open_closed(0.0, 1e5); }  // rpm, the receiver's and the sweep's
inline Range mass_flow() { return Range::open_closed(0.0, 1e4); }  // kg/s, the receiver's and the sweep's
inline Range duration() { return Range::positive(); }              // s, dem.run.duration
constexpr long long kThreadsMax = 1024;                            // dem.run.threads: 0 (all cores) to this
constexpr long long kSeedMax = 2147483647;                         // dem.seed: 0 to this

}  // namespace centrec::config::shared_ranges
