// centrec: DEM of the CentRec particle film, coupling and thermal film model.
#include <cstdio>
#include <exception>
#include <string>

#include "cli/commands.hpp"
#include "config/strict_yaml.hpp"

namespace centrec::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"dem", "run the DEM of a CentRec drum or periodic slice (DEM-only mode)", cmd_dem},
      {"run", "coupled DEM -> film field -> thermal run: outlet temperature, efficiency, k_eff", cmd_run},
      {"export-liggghts", "write a LIGGGHTS 3.8 deck (data, STL, input script) for a case's DEM", cmd_export_liggghts},
      {"scale", "scale a receiver to another size by the paper's eqs 1-3 (keeps omega^2 R, mdot/R, L/R)", cmd_scale},
      {"thermal", "solve the film energy equation under solar flux: T_out, efficiency, k_eff", cmd_thermal},
      {"sweep", "operating map: coupled runs over speed x mass flow in parallel processes", cmd_sweep},
      {"validate", "check a YAML case and print its fully resolved configuration", cmd_validate},
  };
  return table;
}

}  // namespace centrec::cli

namespace {
void print_usage() {
  std::printf("usage: centrec <command> [options]\n\ncommands:\n");
  for (const auto& c : centrec::cli::commands()) std::printf("  %-10s %s\n", c.name, c.summary);
  std::printf("\n'centrec <command> --help' describes each command.\n");
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    print_usage();
    return 2;
  }
  const std::string name = argv[1];
  if (name == "-h" || name == "--help" || name == "help") {
    print_usage();
    return 0;
  }
  centrec::cli::Args args(argv + 2, argv + argc);
  for (const auto& c : centrec::cli::commands()) {
    if (name == c.name) {
      try {
        return c.run(args);
      } catch (const centrec::config::ConfigError& e) {
        std::fprintf(stderr, "centrec %s: configuration error: %s\n", c.name, e.what());
        return 2;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "centrec %s: error: %s\n", c.name, e.what());
        return 1;
      }
    }
  }
  std::fprintf(stderr, "centrec: unknown command '%s'\n\n", name.c_str());
  print_usage();
  return 2;
}
