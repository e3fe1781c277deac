#include "liggghts/liggghts_log_reader.hpp"

#include <algorithm>
#include <deque>
#include <fstream>
#include <sstream>

namespace centrec::liggghts {

bool parse_loop_time(const std::string& line, LiggghtsLoopTime& out) {
  static const std::string head = "Loop time of ";
  if (line.compare(0, head.size(), head) != 0) return false;
  std::istringstream l(line.substr(head.size()));
  std::string on, procs, for_, steps_word, with;
  l >> out.seconds >> on >> out.procs >> procs >> for_ >> out.steps >> steps_word >> with >> out.atoms;
  return static_cast<bool>(l);
}

LiggghtsLogSummary read_liggghts_log(const std::string& path) {
  LiggghtsLogSummary s;
  std::ifstream in(path);
  std::string line;
  std::deque<std::string> before;  // the last few lines, for context
  while (std::getline(in, line)) {
    if (s.version.empty() && line.rfind("LIGGGHTS (Version ", 0) == 0) {
      s.version = line.substr(18);
      if (!s.version.empty() && s.version.back() == ')') s.version.pop_back();
    }
    LiggghtsLoopTime t;
    if (parse_loop_time(line, t)) s.loops.push_back(t);
    if (line.find("ERROR") != std::string::npos) {
      std::string ctx;
      for (const auto& b : before) ctx += "  | " + b + "\n";
      s.errors.push_back(ctx + "  > " + line);
    } else if (line.find("WARNING") != std::string::npos &&
               std::find(s.warnings.begin(), s.warnings.end(), line) == s.warnings.end()) {
      s.warnings.push_back(line);
    }
    before.push_back(line);
    if (before.size() > 3) before.pop_front();
  }
  return s;
}

}  // namespace centrec::liggghts
