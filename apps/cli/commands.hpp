#pragma once
// The `centrec` subcommands. Each lives in its own cmd_<name>.cpp and returns
// the process exit code. Argument vectors exclude the program and subcommand names.
#include <string>
#include <vector>

namespace centrec::cli {

using Args = std::vector<std::string>;

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const Args& args);
};

int cmd_validate(const Args& args);
int cmd_thermal(const Args& args);
int cmd_budget(const Args& args);
int cmd_dem(const Args& args);
int cmd_scale(const Args& args);
int cmd_run(const Args& args);
int cmd_sweep(const Args& args);
int cmd_export_liggghts(const Args& args);
int cmd_keys(const Args& args);
int cmd_paths(const Args& args);
int cmd_operate(const Args& args);

// The table `main` dispatches on; add new subcommands here.
const std::vector<Command>& commands();

}  // namespace centrec::cli
