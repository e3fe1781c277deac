#include "cli/plot_scripts.hpp"

#include "cli/command_line.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

extern char** environ;

namespace centrec::cli {

namespace {

// The system python (Debian's matplotlib, h5py and numpy live there), or CENTREC_PYTHON.
std::string python() {
  const char* env = std::getenv("CENTREC_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

// Exit status of argv[0] run with argv (no shell; stdout and stderr inherited, or sent to
// /dev/null when quiet), -1 if it could not start.
int spawn_and_wait(const std::vector<std::string>& argv, bool quiet = false) {
  std::vector<char*> c;
  for (const auto& a : argv) c.push_back(const_cast<char*>(a.c_str()));
  c.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = 0;
  const int started = posix_spawn(&pid, c[0], &actions, nullptr, c.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::string plot_script_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "centrec" / "scripts";
    if (std::filesystem::exists(installed / "plot_common.py", ec)) return installed.string();
  }
  return CENTREC_PLOT_DIR;
}

void add_figure_flags(CommandLine& app, FigureOptions& f) {
  CLI::Option* none = app.add_flag("--no-plots", f.none, "draw no figures");
  app.add_option("--figures", f.formats, "the figures' formats, comma-separated: png, pdf, svg, eps (default png)")
      ->option_text("LIST")
      ->check(CLI::Validator(
          [](std::string& s) {
            std::stringstream in(s);
            std::string fmt;
            bool any = false;
            while (std::getline(in, fmt, ',')) {
              if (fmt != "png" && fmt != "pdf" && fmt != "svg" && fmt != "eps")
                return "'" + fmt + "' is not a figure format (png, pdf, svg, eps)";
              any = true;
            }
            return any ? std::string() : std::string("no format given (e.g. png,pdf)");
          },
          "LIST"))
      ->excludes(none);
  app.add_option("--dpi", f.dpi, "the figures' resolution in dots per inch (default 130)")
      ->check(integer_in(50, 1200))
      ->option_text("N")
      ->excludes(none);
}

std::vector<std::string> figure_args(const FigureOptions& f) {
  if (f.none) return {"--no-plots"};
  return {"--figures", f.formats, "--dpi", std::to_string(f.dpi)};
}

bool run_plot_script(const std::string& who, const std::string& script, const std::vector<std::string>& args,
                     const FigureOptions& f) {
  if (f.none) return false;
  const char* install = "Debian: apt-get install python3-matplotlib python3-h5py python3-numpy, or ./setup.sh";
  const std::string py = python();
  if (access(py.c_str(), X_OK) != 0) {
    std::fprintf(stderr, "%s: no figures: %s not found (%s); the results are written\n", who.c_str(), py.c_str(), install);
    return false;
  }
  if (spawn_and_wait({py, "-c", "import matplotlib, h5py, numpy"}, true) != 0) {
    std::fprintf(stderr, "%s: no figures: %s lacks matplotlib, h5py or numpy (%s); the results are written\n",
                 who.c_str(), py.c_str(), install);
    return false;
  }
  std::vector<std::string> argv = {py, plot_script_dir() + "/" + script};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"--formats", f.formats, "--dpi", std::to_string(f.dpi)});
  const int rc = spawn_and_wait(argv);
  if (rc != 0) {
    std::string cmd;
    for (const auto& a : argv) cmd += (cmd.empty() ? "" : " ") + a;
    std::fprintf(stderr, "%s: plotting failed (exit %d): %s; the results are written\n", who.c_str(), rc, cmd.c_str());
    return false;
  }
  return true;
}

}  // namespace centrec::cli
