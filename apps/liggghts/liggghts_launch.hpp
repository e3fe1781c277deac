#pragma once
// Launching LIGGGHTS 3.8 under MPI: the command line (OpenMPI's mpirun by default, or a
// cluster launcher such as srun), and running it while polling its output files.
#include <functional>
#include <string>

namespace centrec::liggghts {

struct LiggghtsLaunch {
  std::string mpirun = "mpirun";      // launcher: mpirun/mpiexec (-np N) or srun (-n N)
  std::string liggghts = "liggghts";  // executable
  int ranks = 1;
  std::string work_dir;  // the run's directory (deck paths are relative to it)
  std::string deck;      // input script, relative to work_dir or absolute
  std::string log;       // LIGGGHTS log file
  std::string screen;    // screen output file
};

// The shell command: cd WORK && LAUNCHER -np N liggghts -in DECK -log LOG > SCREEN 2>&1.
std::string liggghts_command(const LiggghtsLaunch& l);

// True if the launcher and the LIGGGHTS executable are found on PATH.
bool liggghts_available(const std::string& mpirun, const std::string& liggghts);

// Runs `cmd` with /bin/sh and returns its exit status (128 + signal if killed).
int run_shell(const std::string& cmd);

// As run_shell, calling `poll` every `interval_s` seconds while the command runs and once after.
int run_shell_polling(const std::string& cmd, const std::function<void()>& poll, double interval_s);

}  // namespace centrec::liggghts
