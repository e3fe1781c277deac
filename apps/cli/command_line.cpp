#include "cli/command_line.hpp"

#include <algorithm>
#include <cmath>

#include "config/strict_yaml.hpp"

namespace centrec::cli {

bool wants_help(const Args& args) {
  for (const auto& a : args)
    if (a == "-h" || a == "--help") return true;
  return false;
}

CommandLine::CommandLine(const std::string& name) : CLI::App("", "centrec " + name) { set_help_flag(); }

void CommandLine::read(const Args& args) {
  // CLI11 takes the arguments last first.
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw config::ConfigError(std::string(e.what()) + " (" + get_name() + " --help)");
  }
}

const CLI::Validator& positive_number() {
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        std::size_t used = 0;
        double x = 0.0;
        try {
          x = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != text.size() || !std::isfinite(x) || !(x > 0.0)) return "'" + text + "' is not a positive number";
        return {};
      },
      "POSITIVE");
  return v;
}

}  // namespace centrec::cli
