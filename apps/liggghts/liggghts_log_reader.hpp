#pragma once
// Reading a LIGGGHTS 3.8 log: its version line, "Loop time" lines, and the ERROR and
// WARNING lines with the commands that led to them (for failure reports).
#include <string>
#include <vector>

namespace centrec::liggghts {

// "Loop time of T on P procs for S steps with N atoms"
struct LiggghtsLoopTime {
  double seconds = 0.0;
  long procs = 0, steps = 0, atoms = 0;
};
bool parse_loop_time(const std::string& line, LiggghtsLoopTime& out);

struct LiggghtsLogSummary {
  std::string version;                     // e.g. "LIGGGHTS-PUBLIC 3.8.0, compiled ..."
  std::vector<LiggghtsLoopTime> loops;     // one per `run`
  std::vector<std::string> errors;         // each ERROR line with up to 3 lines before it
  std::vector<std::string> warnings;       // distinct WARNING lines
};

// Reads the log (a missing file gives an empty summary).
LiggghtsLogSummary read_liggghts_log(const std::string& path);

}  // namespace centrec::liggghts
