#include <stdexcept>

#include "cli/commands.hpp"

namespace centrec::cli {

bool wants_help(const Args& args) {
  for (const auto& a : args)
    if (a == "-h" || a == "--help") return true;
  return false;
}

void parse_case_args(const Args& args, const std::string& help, std::string& case_path,
                     const std::function<bool(const std::string&, const std::function<std::string()>&)>& option) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const std::function<std::string()> value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value (" + help + ")");
      return args[++i];
    };
    if (!a.empty() && a[0] == '-') {
      if (!option(a, value)) throw std::invalid_argument("unknown option " + a + " (" + help + ")");
    } else if (case_path.empty()) {
      case_path = a;
    } else {
      throw std::invalid_argument("more than one case file given (" + help + ")");
    }
  }
  if (case_path.empty()) throw std::invalid_argument("no case file given (" + help + ")");
}

}  // namespace centrec::cli
