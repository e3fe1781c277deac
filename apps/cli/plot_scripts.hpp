#pragma once
// The figures of a run: the commands call the plot scripts (apps/plot_*.py, installed to
// share/centrec/scripts) with the system python (/usr/bin/python3 with matplotlib, h5py and
// numpy, which ./setup.sh installs; CENTREC_PYTHON names another interpreter). Plotting never
// fails a run: without python or its packages the command says so on stderr and goes on
// (docs/outputs.md).
#include <string>
#include <vector>

namespace centrec::cli {

// Runs `python3 SCRIPT ARGS...` (no shell) and prints its "wrote ..." lines; who names the
// command in messages ("centrec run"). Returns true when the script ran and succeeded.
bool run_plot_script(const std::string& who, const std::string& script, const std::vector<std::string>& args);

// Where the scripts are: next to the installed binary (../share/centrec/scripts), else the
// source tree's apps/ the binary was built from.
std::string plot_script_dir();

}  // namespace centrec::cli
