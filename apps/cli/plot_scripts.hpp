#pragma once
// The figures of a run: the commands call the plot scripts (apps/plot_*.py, installed to
// share/centrec/scripts) with the system python (/usr/bin/python3 with matplotlib, h5py and
// numpy, which ./setup.sh installs; CENTREC_PYTHON names another interpreter). Plotting never
// fails a run: without python or its packages the command says so on stderr and goes on
// (docs/outputs.md).
#include <string>
#include <vector>

namespace centrec::cli {

class CommandLine;

// What figures a command draws: none (--no-plots), or each figure in these formats at this
// resolution (--figures png,pdf,svg --dpi 300; PNG at 130 dpi by default).
struct FigureOptions {
  bool none = false;
  std::string formats = "png";  // comma-separated: png, pdf, svg, eps
  int dpi = 130;
};

// Declares --no-plots, --figures and --dpi on `app`.
void add_figure_flags(CommandLine& app, FigureOptions& f);

// The figure flags as given, for a child process's command line.
std::vector<std::string> figure_args(const FigureOptions& f);

// Runs `python3 SCRIPT ARGS... --formats F --dpi N` (no shell) and prints its "wrote ..."
// lines; who names the command in messages ("centrec run"). Returns true when the script
// ran and succeeded; draws nothing (and returns false) with f.none.
bool run_plot_script(const std::string& who, const std::string& script, const std::vector<std::string>& args,
                     const FigureOptions& f);

// Where the scripts are: next to the installed binary (../share/centrec/scripts), else the
// source tree's apps/ the binary was built from.
std::string plot_script_dir();

}  // namespace centrec::cli
