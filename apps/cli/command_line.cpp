#include "cli/command_line.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace centrec::cli {

bool wants_help(const Args& args) {
  for (const auto& a : args)
    if (a == "-h" || a == "--help") return true;
  return false;
}

CommandLine::CommandLine(const std::string& name) : CLI::App("", "centrec " + name) { set_help_flag(); }

void CommandLine::read(const Args& args) {
  const std::string help = " (" + get_name() + " --help)";
  // An unknown option is named with the closest known one before CLI11 sees it (CLI11
  // would take it as a positional argument or report every leftover word).
  std::vector<std::string> names;
  for (const CLI::Option* o : get_options())
    for (const auto& n : o->get_lnames()) names.push_back("--" + n);
  for (const auto& a : args) {
    if (a.size() < 2 || a[0] != '-') continue;
    char* end = nullptr;
    std::strtod(a.c_str(), &end);
    if (end == a.c_str() + a.size()) continue;  // a negative number: an option's value
    const std::string name = a.substr(0, a.find('='));
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    const std::string near = config::closest_word(name, names);
    throw UsageError("unknown option '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") + help);
  }
  // CLI11 takes the arguments last first.
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    parse(reversed);
  } catch (const CLI::ExtrasError& e) {
    throw UsageError("unexpected argument(s): " + std::string(e.what()).substr(std::string(e.what()).find(':') + 1) + help);
  } catch (const CLI::ParseError& e) {
    throw UsageError(std::string(e.what()) + help);
  }
}

const CLI::Validator& positive_number() {
  static const CLI::Validator v = number_in(config::Range::positive());
  return v;
}

CLI::Validator number_in(const config::Range& range, const std::string& unit) {
  return CLI::Validator(
      [range, unit](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
        if (!std::isfinite(x) || errno == ERANGE) return "'" + text + "' is not a finite number";
        if (!range.contains(x))
          return text + " is out of the allowed range " + range.describe() + (unit.empty() ? "" : " " + unit);
        return {};
      },
      "NUMBER");
}

CLI::Validator integer_in(long lo, long hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long x = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a whole number";
        if (errno == ERANGE || x < lo || x > hi)
          return text + " is out of the allowed range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        return {};
      },
      "INTEGER");
}

}  // namespace centrec::cli
