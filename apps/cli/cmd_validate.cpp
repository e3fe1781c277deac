#include <cstdio>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_file.hpp"

namespace centrec::cli {

int cmd_validate(const Args& args) {
  if (wants_help(args) || args.empty()) {
    std::printf(
        "usage: centrec validate CASE.yaml\n\n"
        "Reads CASE.yaml with the same strict rules as every run (unknown keys, wrong\n"
        "types and out-of-range values are errors naming the key path and line) and\n"
        "prints the fully resolved configuration, defaults included.\n");
    return wants_help(args) ? 0 : 2;
  }
  std::string case_path;
  CommandLine app("validate");
  app.add_option("CASE", case_path)->required();
  app.read(args);
  const config::CaseFile c = config::read_case_file(case_path);
  std::printf("# %s: valid\n%s\n", c.path.c_str(), c.resolved_yaml.c_str());
  return 0;
}

}  // namespace centrec::cli
