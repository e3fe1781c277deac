#pragma once
// The `centrec` subcommands. Each lives in its own cmd_<name>.cpp and returns
// the process exit code. Argument vectors exclude the program and subcommand names.
#include <functional>
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
int cmd_dem(const Args& args);
int cmd_scale(const Args& args);
int cmd_run(const Args& args);
int cmd_sweep(const Args& args);
int cmd_export_liggghts(const Args& args);

// The table `main` dispatches on; add new subcommands here.
const std::vector<Command>& commands();

// True if args contain -h or --help.
bool wants_help(const Args& args);

// Reads `CASE.yaml [--option value | --flag]...`: each option goes to option(name, value)
// where value() takes the next argument; option returns false for an unknown name.
// Throws std::invalid_argument naming the problem and `help` (e.g. "centrec run --help").
void parse_case_args(const Args& args, const std::string& help, std::string& case_path,
                     const std::function<bool(const std::string& name, const std::function<std::string()>& value)>& option);

}  // namespace centrec::cli
