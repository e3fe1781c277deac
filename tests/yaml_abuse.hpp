#pragma once
// YAML that no case file is, for the case reader's tests (docs/reliability.md "Case files").
#include <string>

namespace centrec::testing {

// Nine levels of ten aliases each: ten lines that stand for 1e9 values once expanded.
inline std::string alias_bomb() {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int k = 1; k <= 9; ++k) {
    const std::string p = "*l" + std::to_string(k - 1);
    text += "l" + std::to_string(k) + ": &l" + std::to_string(k) + " [" + p;
    for (int i = 1; i < 10; ++i) text += ", " + p;
    text += "]\n";
  }
  return text;
}

}  // namespace centrec::testing
