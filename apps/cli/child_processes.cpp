#include "cli/child_processes.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace centrec::cli {

std::string own_executable() {
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) throw std::runtime_error("centrec: cannot find its own executable");
  exe[n] = '\0';
  return exe;
}

namespace {
pid_t start(const ChildJob& job) {
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("centrec: fork failed");
  if (pid == 0) {
    const int fd = open(job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    std::vector<char*> argv;
    for (const auto& s : job.argv) argv.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}
}  // namespace

int run_child_jobs(std::vector<ChildJob>& jobs, int parallel, const std::function<void(std::size_t)>& on_start,
                   const std::function<void(std::size_t)>& on_done) {
  if (parallel < 1) parallel = 1;
  std::size_t next = 0, done = 0;
  int failed = 0;
  std::vector<std::pair<pid_t, std::size_t>> running;
  while (done < jobs.size()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      running.push_back({start(jobs[next]), next});
      if (on_start) on_start(next);
      ++next;
    }
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid < 0 && errno == EINTR) continue;  // a signal to this process: the children get it too
    if (pid < 0) throw std::runtime_error("centrec: wait for a child process failed");
    for (std::size_t k = 0; k < running.size(); ++k) {
      if (running[k].first != pid) continue;
      ChildJob& job = jobs[running[k].second];
      job.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
      failed += job.status != 0;
      ++done;
      if (on_done) on_done(running[k].second);
      running.erase(running.begin() + static_cast<long>(k));
      break;
    }
  }
  return failed;
}

std::string failure_reason(const ChildJob& job) {
  std::ifstream in(job.log);
  std::string line, error, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    last = line;
    if (line.find("error: ") != std::string::npos) error = line;
  }
  return error.empty() ? last : error;
}

}  // namespace centrec::cli
