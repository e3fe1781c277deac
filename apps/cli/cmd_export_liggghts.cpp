// `centrec export-liggghts CASE.yaml --out DIR`: the case as a LIGGGHTS 3.8 deck.
#include <cstdio>
#include <stdexcept>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/run_folder.hpp"
#include "liggghts/liggghts_export.hpp"

namespace centrec::cli {

int cmd_export_liggghts(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec export-liggghts CASE.yaml --out DIR [--wall-rolling-model relative|liggghts] [--overwrite]\n\n"
        "Writes a complete, commented LIGGGHTS 3.8 deck for the case's `dem:` section into DIR:\n"
        "in.centrec (the deck), data.centrec (glued rough-wall spheres and the starting film),\n"
        "drum.stl (cylinder, back plate, outlet lip) and outlet.stl (the counting face).\n"
        "Run it with `mpirun -np N liggghts -in in.centrec` from DIR, or use\n"
        "`centrec dem CASE.yaml --engine liggghts`, which also reads the results back.\n"
        "Settings LIGGGHTS cannot express (e.g. wall_rolling_model: relative) are refused.\n");
    return 0;
  }
  std::string case_path, out_dir;
  bool overwrite = false;
  config::Overrides overrides;
  CommandLine app("export-liggghts");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir)->required();
  add_override_flags(app, overrides, "export-liggghts");
  add_overwrite_flag(app, overwrite);
  app.read(args);
  const config::CaseFile cf = checked_overrides(config::read_case_file(case_path), overrides, "export-liggghts");
  if (!cf.dem) throw std::invalid_argument(case_path + " has no `dem:` section");
  // The drum `centrec dem` and `centrec run` simulate: the one the receiver derives
  // (receiver.dem_diameter_d, eqs 1-3) when it does, with the same checks.
  const config::DemCase dc = checked_dem(cf, overrides, "export-liggghts");
  // A deck is not written among a run's files, nor over an earlier deck (perhaps edited by
  // hand) unless --overwrite (io/run_folder.hpp).
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec export-liggghts " + case_path, folder_use(overwrite));
  const liggghts::LiggghtsDeckPlan plan = liggghts::export_liggghts(cf, dc, out_dir);
  std::printf("wrote %s/%s: dt %.3g s, %lld glued + %lld free particles, %lld + %lld steps, dumps every %lld steps\n",
              out_dir.c_str(), plan.deck.c_str(), plan.dt, static_cast<long long>(plan.glued),
              static_cast<long long>(plan.initial_free), static_cast<long long>(plan.spinup_steps),
              static_cast<long long>(plan.sampling_steps), static_cast<long long>(plan.dump_every));
  std::printf("  %s\n", config::dem_drum_line(dc, cf.receiver && cf.receiver->dem_diameter_d > 0.0).c_str());
  for (const std::string& d : plan.differences) std::printf("  differs from the native engine: %s\n", d.c_str());
  return 0;
}

}  // namespace centrec::cli
