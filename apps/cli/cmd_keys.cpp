// `centrec keys`: prints the case-key reference (docs/case_keys.md) as Markdown, recorded
// from the case readers themselves (apps/config/case_keys.hpp).
#include <cstdio>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_keys.hpp"

namespace centrec::cli {

int cmd_keys(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec keys\n\n"
        "Prints every case-file key (section, key, type, default, allowed values, unit, meaning)\n"
        "as Markdown, recorded from the case readers as they read: docs/case_keys.md is this output\n"
        "(regenerate it with `centrec keys > docs/case_keys.md`).\n");
    return 0;
  }
  CommandLine app("keys");
  app.read(args);
  std::fputs(config::case_keys_markdown(config::case_keys()).c_str(), stdout);
  return 0;
}

}  // namespace centrec::cli
