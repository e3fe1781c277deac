#pragma once
// Runs the real `centrec` binary in a child process with a wall-clock limit, so a crash
// (a signal) or a hang (the limit) is observed rather than taken down with the test.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace centrec::testing {

struct BinaryRun {
  int exit_code = -1;   // when it exited
  int signal = 0;       // when a signal ended it (a crash, or the limit's SIGKILL)
  bool timed_out = false;
  std::string out, err;
};

// Starts `centrec args...`; with `interrupt_after` > 0 s sends it SIGINT then (once), counted
// from the moment its stderr first holds `interrupt_on` when that is given (a phase of the
// run, so the moment does not depend on how loaded the machine is); with `address_space` > 0
// bytes the child runs under that limit (ulimit -v), so an allocation beyond it fails as it
// would on a machine without the memory.
inline BinaryRun run_binary(const std::vector<std::string>& args, double limit_s = 30.0, double interrupt_after = 0.0,
                            std::size_t address_space = 0, const std::string& interrupt_on = "") {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string tag = std::to_string(::getpid());
  const std::string out_path = (dir / ("centrec_out_" + tag)).string(), err_path = (dir / ("centrec_err_" + tag)).string();
  const pid_t child = ::fork();
  if (child == 0) {
    const int o = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (address_space > 0) {
      const rlimit lim{static_cast<rlim_t>(address_space), static_cast<rlim_t>(address_space)};
      ::setrlimit(RLIMIT_AS, &lim);
    }
    std::vector<char*> argv{const_cast<char*>(CENTREC_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(CENTREC_BINARY, argv.data());
    ::_exit(127);
  }
  BinaryRun r;
  const auto t0 = std::chrono::steady_clock::now();
  bool interrupted = false;
  double armed_at = interrupt_on.empty() ? 0.0 : -1.0;  // when the count to the SIGINT started
  int status = 0;
  for (;;) {
    const pid_t w = ::waitpid(child, &status, WNOHANG);
    if (w == child) break;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (interrupt_after > 0.0 && armed_at < 0.0) {
      std::ifstream in(err_path);
      const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (err.find(interrupt_on) != std::string::npos) armed_at = t;
    }
    if (interrupt_after > 0.0 && !interrupted && armed_at >= 0.0 && t - armed_at >= interrupt_after) {
      ::kill(child, SIGINT);
      interrupted = true;
    }
    if (t > limit_s) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  r.out = slurp(out_path);
  r.err = slurp(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return r;
}

}  // namespace centrec::testing
