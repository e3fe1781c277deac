#include <cstdio>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_checks.hpp"
#include "config/case_file.hpp"

namespace centrec::cli {

int cmd_validate(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec validate CASE.yaml\n\n"
        "Reads CASE.yaml with the same strict rules as every run (unknown keys, wrong\n"
        "types and out-of-range values are errors naming the key path and line), makes\n"
        "every check `centrec dem` and `centrec run` make before they start (time step,\n"
        "drum, feeder, step count, particles of a coupled case) and prints the DEM drum\n"
        "the runs simulate (derived from the receiver when it derives one) and the fully\n"
        "resolved configuration, defaults included.\n");
    return 0;
  }
  if (args.empty()) throw UsageError("no case file given (centrec validate --help)");
  std::string case_path;
  CommandLine app("validate");
  app.add_option("CASE", case_path)->required();
  app.read(args);
  const config::CaseFile c = config::read_case_file(case_path);
  std::printf("# %s: valid\n", c.path.c_str());
  if (c.dem) {
    const config::ReceiverCase* receiver = c.receiver ? &*c.receiver : nullptr;
    std::printf("# %s\n", config::dem_drum_line(config::effective_dem(*c.dem, receiver, {}),
                                                receiver && receiver->dem_diameter_d > 0.0)
                                 .c_str());
  }
  std::printf("%s\n", c.resolved_yaml.c_str());
  return 0;
}

}  // namespace centrec::cli
