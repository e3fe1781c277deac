#pragma once
// The one option parser of every subcommand, on CLI11: a command declares its options,
// each bound to one of its variables, on a CommandLine and reads its arguments with read(). Every command prints its own --help text, so the
// parser has no help flag (wants_help in commands.hpp decides first).
#include <CLI/CLI.hpp>
#include <string>

#include "cli/commands.hpp"

namespace centrec::cli {

// True if args contain -h or --help.
bool wants_help(const Args& args);

// The parser of `centrec <name>`: CLI11's App without its help flag.
class CommandLine : public CLI::App {
 public:
  explicit CommandLine(const std::string& name);
  // Reads args into the options declared on it; throws config::ConfigError naming the
  // problem and `centrec <name> --help`.
  void read(const Args& args);
};

// Accepts a finite number above zero, written without trailing characters.
const CLI::Validator& positive_number();

}  // namespace centrec::cli
