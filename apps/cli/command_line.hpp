#pragma once
// The one option parser of every subcommand, on CLI11: a command declares its options,
// each bound to one of its variables, on a CommandLine and reads its arguments with read(). Every command prints its own --help text, so the
// parser has no help flag (wants_help in commands.hpp decides first).
#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "config/strict_yaml.hpp"
#include "io/run_folder.hpp"

namespace centrec::cli {

// A command line that cannot run: a missing or unknown option, a value out of range (a
// configuration error given on the command line). `main` prints it as
// "centrec <command>: usage error: ..." and exits with 2.
class UsageError : public config::ConfigError {
 public:
  using config::ConfigError::ConfigError;
};

// True if args contain -h or --help.
bool wants_help(const Args& args);

// The parser of `centrec <name>`: CLI11's App without its help flag.
class CommandLine : public CLI::App {
 public:
  explicit CommandLine(const std::string& name);
  // Reads args into the options declared on it; throws UsageError naming the problem in
  // one line (an unknown option with the closest known one) and `centrec <name> --help`.
  void read(const Args& args);
  // Every option declared with a help text, one per line in declaration order:
  // "  --name VALUE   help" (VALUE = the option's value name; a flag has none).
  std::string options_text() const;
  // Whether `name` ("--cache") is a declared option that takes a value.
  bool takes_value(const std::string& name) const;
};

// `args` without the options `names` (and their values): the command a child process
// repeats with its own values of them.
Args without_options(const CommandLine& app, const Args& args, const std::vector<std::string>& names);

// Accepts a finite number above zero, written without trailing characters.
const CLI::Validator& positive_number();
// Accepts a finite number inside `range` (unit for the message).
CLI::Validator number_in(const config::Range& range, const std::string& unit = "");
// Accepts a whole number in [lo, hi].
CLI::Validator integer_in(long lo, long hi);

// `--overwrite` of the commands that write a run folder (io/run_folder.hpp), and the folder
// use it asks for.
void add_overwrite_flag(CommandLine& app, bool& overwrite);
io::FolderUse folder_use(bool overwrite);

}  // namespace centrec::cli
