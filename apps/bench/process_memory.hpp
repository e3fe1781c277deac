#pragma once
// Resident set size of this process (Linux /proc/self/status), for a memory cross-check
// of an engine's own byte count.
#include <cstddef>

namespace centrec::bench {

// VmRSS in bytes; 0 if unavailable.
std::size_t resident_bytes();

}  // namespace centrec::bench
