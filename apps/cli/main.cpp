// centrec: DEM of the CentRec particle film, coupling and thermal film model.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/strict_yaml.hpp"
#include "io/code_version.hpp"

namespace centrec::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"dem", "run the DEM of a CentRec drum or periodic slice (DEM-only mode)", cmd_dem},
      {"run", "coupled DEM -> film field -> thermal run: outlet temperature, efficiency, k_eff", cmd_run},
      {"export-liggghts", "write a LIGGGHTS 3.8 deck (data, STL, input script) for a case's DEM", cmd_export_liggghts},
      {"scale", "scale a receiver to another size by the paper's eqs 1-3 (keeps omega^2 R, mdot/R, L/R)", cmd_scale},
      {"thermal", "solve the film energy equation under solar flux: T_out, efficiency, k_eff", cmd_thermal},
      {"budget", "error budget: the inputs' stated uncertainties propagated to T_out, efficiency, k_eff", cmd_budget},
      {"paths", "a fed drum's residence times and its particles heated along their own paths", cmd_paths},
      {"sweep", "a study: coupled runs over a grid of case keys (speed x mass flow by default) in parallel", cmd_sweep},
      {"operate", "the speed and mass flow that reach a target outlet temperature, from an operating map",
       cmd_operate},
      {"validate", "check a YAML case; print the DEM drum it runs and its fully resolved configuration", cmd_validate},
      {"keys", "print every case-file key with type, default, range, unit and meaning (Markdown)", cmd_keys},
  };
  return table;
}

}  // namespace centrec::cli

namespace {
void print_usage(std::FILE* to = stdout) {
  std::fprintf(to, "usage: centrec <command> [options]    (centrec --version: the code version)\n\ncommands:\n");
  int width = 0;
  for (const auto& c : centrec::cli::commands()) width = std::max(width, static_cast<int>(std::strlen(c.name)));
  for (const auto& c : centrec::cli::commands()) std::fprintf(to, "  %-*s  %s\n", width, c.name, c.summary);
  std::fprintf(to, "\n'centrec <command> --help' describes each command.\n");
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "centrec: usage error: no command given\n");
    print_usage(stderr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "-h" || name == "--help" || name == "help") {
    print_usage();
    return 0;
  }
  if (name == "--version" || name == "-V" || name == "version") {
    std::printf("centrec %s\n", centrec::io::code_version());
    return 0;
  }
  centrec::cli::Args args(argv + 2, argv + argc);
  std::vector<std::string> names;
  for (const auto& c : centrec::cli::commands()) {
    names.push_back(c.name);
    if (name != c.name) continue;
    // Every failure is one line on stderr naming the command; the exit code says which kind.
    try {
      return c.run(args);
    } catch (const centrec::cli::UsageError& e) {
      std::fprintf(stderr, "centrec %s: usage error: %s\n", c.name, e.what());
      return 2;
    } catch (const centrec::config::ConfigError& e) {
      std::fprintf(stderr, "centrec %s: configuration error: %s\n", c.name, e.what());
      return 2;
    } catch (const std::bad_alloc&) {
      std::fprintf(stderr, "centrec %s: error: out of memory (the case asks for more particles, grid cells or "
                           "samples than this machine holds)\n", c.name);
      return 1;
    } catch (const std::length_error& e) {
      std::fprintf(stderr, "centrec %s: error: a size beyond what can be allocated (%s): the case asks for too "
                           "many particles, grid cells or samples\n", c.name, e.what());
      return 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "centrec %s: error: %s\n", c.name, e.what());
      return 1;
    }
  }
  const std::string near = centrec::config::closest_word(name, names);
  std::fprintf(stderr, "centrec: usage error: unknown command '%s'%s\n\n", name.c_str(),
               near.empty() ? "" : (" (did you mean '" + near + "'?)").c_str());
  print_usage(stderr);
  return 2;
}
