#pragma once
// A random generator's state as text (the std::mt19937_64 stream format), so the scene's
// generators survive a checkpoint and continue the same sequence.
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace centrec::dem::scene {

inline std::string rng_text(const std::mt19937_64& g) {
  std::ostringstream out;
  out << g;
  return out.str();
}

// Throws std::invalid_argument naming `who` if the text is not a generator state.
inline void read_rng_text(const std::string& text, std::mt19937_64& g, const std::string& who) {
  std::istringstream in(text);
  in >> g;
  if (in.fail()) throw std::invalid_argument(who + ": unreadable generator state");
}

}  // namespace centrec::dem::scene
