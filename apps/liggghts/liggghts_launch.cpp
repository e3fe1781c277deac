#include "liggghts/liggghts_launch.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace centrec::liggghts {
namespace {

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string basename_of(const std::string& p) {
  const auto k = p.find_last_of('/');
  return k == std::string::npos ? p : p.substr(k + 1);
}

int exit_status(int status) {
  if (status == -1) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

std::string liggghts_command(const LiggghtsLaunch& l) {
  std::string cmd = "cd " + quoted(l.work_dir) + " && ";
  const std::string launcher = basename_of(l.mpirun);
  if (launcher == "srun") {
    cmd += l.mpirun + " -n " + std::to_string(l.ranks);
  } else {
    cmd += l.mpirun;
    // OpenMPI: root needs consent; --bind-to none because pinning ranks to cores other
    // processes of a shared machine also use slows everyone; --oversubscribe never
    // refuses more ranks than cores.
    if (launcher == "mpirun" || launcher == "mpiexec") {
      if (geteuid() == 0) cmd += " --allow-run-as-root";
      cmd += " --oversubscribe --bind-to none";
    }
    cmd += " -np " + std::to_string(l.ranks);
  }
  // Screen output goes to a file: "-screen none" crashes the Debian LIGGGHTS 3.8 build.
  cmd += " " + quoted(l.liggghts) + " -in " + quoted(l.deck) + " -log " + quoted(l.log) + " > " + quoted(l.screen) +
         " 2>&1";
  return cmd;
}

bool liggghts_available(const std::string& mpirun, const std::string& liggghts) {
  return run_shell("command -v " + quoted(mpirun) + " >/dev/null 2>&1 && command -v " + quoted(liggghts) +
                   " >/dev/null 2>&1") == 0;
}

int run_shell(const std::string& cmd) { return exit_status(std::system(cmd.c_str())); }

int run_shell_polling(const std::string& cmd, const std::function<void()>& poll, double interval_s) {
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start: " + cmd);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0) throw std::runtime_error("lost track of: " + cmd);
    poll();
    std::this_thread::sleep_for(std::chrono::duration<double>(interval_s));
  }
  poll();
  return exit_status(status);
}

}  // namespace centrec::liggghts
