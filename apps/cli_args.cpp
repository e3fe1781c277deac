#include "commands.hpp"

namespace centrec::cli {

bool wants_help(const Args& args) {
  for (const auto& a : args)
    if (a == "-h" || a == "--help") return true;
  return false;
}

}  // namespace centrec::cli
