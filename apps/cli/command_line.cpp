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

std::string CommandLine::options_text() const {
  std::vector<std::pair<std::string, std::string>> rows;
  std::size_t width = 0;
  for (const CLI::Option* o : get_options()) {
    if (o->get_description().empty() || o->get_lnames().empty()) continue;
    std::string name = "--" + o->get_lnames().front();
    if (o->get_expected_max() > 0) name += " " + (o->get_option_text().empty() ? std::string("VALUE") : o->get_option_text());
    width = std::max(width, name.size());
    rows.emplace_back(name, o->get_description());
  }
  std::string text;
  for (const auto& [name, help] : rows) text += "  " + name + std::string(width + 3 - name.size(), ' ') + help + "\n";
  return text;
}

bool CommandLine::takes_value(const std::string& name) const {
  for (const CLI::Option* o : get_options())
    for (const auto& n : o->get_lnames())
      if ("--" + n == name) return o->get_expected_max() > 0;
  return false;
}

Args without_options(const CommandLine& app, const Args& args, const std::vector<std::string>& names) {
  Args kept;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    const std::string name = a.substr(0, a.find('='));
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      kept.push_back(a);
      continue;
    }
    if (name == a && app.takes_value(name)) ++k;  // "--seed 3": its value too
  }
  return kept;
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

void add_overwrite_flag(CommandLine& app, bool& overwrite) {
  app.add_flag("--overwrite", overwrite,
               "replace the results (or the interrupted run) that DIR holds: their files are removed first");
}

io::FolderUse folder_use(bool overwrite) { return overwrite ? io::FolderUse::overwrite : io::FolderUse::new_run; }

}  // namespace centrec::cli
