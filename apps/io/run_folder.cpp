#include "io/run_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace centrec::io {

namespace fs = std::filesystem;

namespace {
// What the commands write into a run folder (docs/outputs.md): a folder holding any of them
// holds a run.
const char* const kRunFiles[] = {
    "summary.json", "dem.h5",     "dem.xmf",    "drum.xmf",  "mass_flow.csv", "checkpoint.h5", "results.h5",
    "results.xmf",  "film.h5",    "thermal.h5", "thermal.xmf", "sweep.json",  "sweep.csv",     "tracks",
    "paths.csv",    "along_z.csv", "film_profiles.csv",
    "liggghts",  // --engine liggghts's deck and dumps
    // a LIGGGHTS deck (export-liggghts; liggghts/liggghts_export.hpp)
    "in.centrec", "data.centrec", "drum.stl", "drum_ends.stl", "outlet.stl", "dumps", "mass_flow.txt",
    "log.liggghts", "screen.liggghts"};

bool alive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}
}  // namespace

std::vector<std::string> run_files_in(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const char* f : kRunFiles)
    if (fs::exists(fs::path(dir) / f, ec)) out.push_back(f);
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".png") out.push_back(e.path().filename().string());
  return out;
}

RunFolderClaim::RunFolderClaim(const std::string& dir, const std::string& command, FolderUse use)
    : lock_(dir + "/.centrec-run.lock") {
  // The lock first, so that two runs starting together cannot both pass the checks below.
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = ::open(lock_.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const std::string text = "pid " + std::to_string(::getpid()) + "\ncommand " + command + "\n";
      const ssize_t n = ::write(fd, text.data(), text.size());
      ::close(fd);
      if (n != static_cast<ssize_t>(text.size())) {
        ::unlink(lock_.c_str());
        throw std::invalid_argument("cannot write the run lock " + lock_ + " (a full disk?)");
      }
      break;
    }
    if (errno != EEXIST || attempt == 1) {
      lock_.clear();
      throw std::invalid_argument("cannot claim the run folder " + dir + ": " + std::strerror(errno));
    }
    std::ifstream in(lock_);
    std::string key, owner_command;
    long pid = 0;
    in >> key >> pid;
    std::getline(in >> std::ws, owner_command);
    if (alive(pid)) {
      const std::string held = lock_;
      lock_.clear();  // not ours: the destructor leaves it
      throw std::invalid_argument(dir + " is in use by another centrec run (process " + std::to_string(pid) + ": " +
                                  owner_command.substr(owner_command.find(' ') + 1) +
                                  "): wait for it to end or give another --out (if process " + std::to_string(pid) +
                                  " is no centrec run, remove " + held + ")");
    }
    ::unlink(lock_.c_str());  // its process is gone (killed): the folder is judged by its files
  }
  const std::vector<std::string> files = run_files_in(dir);
  const bool checkpoint = fs::exists(fs::path(dir) / "checkpoint.h5"),
             finished = fs::exists(fs::path(dir) / "summary.json") || fs::exists(fs::path(dir) / "sweep.json");
  try {
    if (use == FolderUse::resume) {
      if (!checkpoint) throw std::invalid_argument(dir + " holds no checkpoint.h5 to resume from");
      // A finished run keeps its last checkpoint (a settled start reads it); resuming it
      // would run its last stretch again and rewrite its results.
      if (finished)
        throw std::invalid_argument(dir + " holds a finished run (summary.json): there is nothing to resume");
      return;
    }
    if (files.empty()) return;
    if (use == FolderUse::new_run) {
      if (checkpoint && !finished)
        throw std::invalid_argument(dir + " holds an interrupted run with its checkpoint (" + joined(files) +
                                    "): continue it with `centrec dem --resume " + dir +
                                    "`, or give --overwrite to start again in it");
      throw std::invalid_argument(dir + " holds the results of an earlier run (" + joined(files) +
                                  "): give another --out, or --overwrite to replace them");
    }
    for (const auto& f : files) fs::remove_all(fs::path(dir) / f);  // overwrite: none of the old run's files stay
  } catch (...) {
    ::unlink(lock_.c_str());
    lock_.clear();
    throw;
  }
}

RunFolderClaim::~RunFolderClaim() {
  if (!lock_.empty()) ::unlink(lock_.c_str());
}

}  // namespace centrec::io
