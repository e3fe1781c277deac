#pragma once
// Commands that run other `centrec` commands as child processes, a few at a time
// (`centrec sweep` over its grid, `centrec run --replicas` over seeds).
#include <functional>
#include <string>
#include <vector>

namespace centrec::cli {

struct ChildJob {
  std::vector<std::string> argv;  // argv[0] = the executable
  std::string log;                // the child's stdout and stderr go here
  int status = -1;                // exit status once done (128 + signal when killed)
};

// The path of the running executable (/proc/self/exe), so children run the same build.
std::string own_executable();

// Runs every job, at most `parallel` at a time; calls on_start / on_done (may be empty)
// with the job's index as each starts and ends. Returns the number of jobs that failed.
int run_child_jobs(std::vector<ChildJob>& jobs, int parallel, const std::function<void(std::size_t)>& on_start,
                   const std::function<void(std::size_t)>& on_done);

// Why a finished job failed, from its log: the last line naming an error ("...: error: ..."),
// else the log's last non-empty line, else "". Lines are returned without their newline.
std::string failure_reason(const ChildJob& job);

}  // namespace centrec::cli
