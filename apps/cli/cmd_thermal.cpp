#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_thermal.hpp"
#include "io/atomic_write.hpp"
#include "io/summary_json.hpp"
#include "runs/thermal_case_run.hpp"
#include "runs/thermal_output.hpp"

namespace centrec::cli {

int cmd_thermal(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec thermal CASE.yaml --out DIR [--overwrite]\n\n"
        "Solves the energy equation of the particle film under concentrated solar flux\n"
        "(docs/thermal_model.md): the steady state of the operating point (2D on z x xi = eta/t,\n"
        "or the 1D depth-lumped model), then the transient if the case has `thermal.transient`\n"
        "(flux step, cloud passage, mass-flow change). The film comes from `film.analytic` or\n"
        "from a film-field HDF5 file `film.file` (group /film, docs/coupling.md).\n\n"
        "Writes DIR/thermal.h5 (T, k fields, local fluxes, k_eff per section, transient\n"
        "series; units as attributes; the resolved configuration and the code version as root\n"
        "attributes), DIR/thermal.xmf (the temperature field on its grid, for ParaView) and\n"
        "DIR/summary.json (outlet mixing-cup temperature, efficiency, powers,\n"
        "energy-balance residual, k_eff, solver statistics). Plot: apps/plot_thermal.py DIR.\n"
        "Examples: cases/thermal_*.yaml.\n");
    return 0;
  }
  if (args.empty()) throw UsageError("no case file given (centrec thermal --help)");
  std::string case_path, out_dir;
  CommandLine app("thermal");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir)->required();
  bool overwrite = false;
  add_overwrite_flag(app, overwrite);
  config::Overrides overrides;  // --set
  add_override_flags(app, overrides, "thermal");
  app.read(args);
  const config::ThermalCase c =
      config::thermal_case_of(checked_overrides(config::read_case_file(case_path), overrides, "thermal"));
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec thermal " + case_path, folder_use(overwrite));
  const auto t0 = std::chrono::steady_clock::now();
  const runs::ThermalRun r = runs::run_thermal_case(c);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  runs::write_thermal_h5(out_dir + "/thermal.h5", c, r);
  io::write_text_atomically(out_dir + "/along_z.csv", runs::along_z_csv(r));
  io::write_text_atomically(out_dir + "/film_profiles.csv", runs::film_profiles_csv(c.film));
  nlohmann::json summary = runs::thermal_summary(c, r);
  summary["wall_time_s"] = seconds;
  if (!flags_text(overrides, "thermal").empty()) summary["command_line_overrides"] = flags_text(overrides, "thermal");
  io::write_json_file(out_dir + "/summary.json", summary);
  const auto& b = r.balance;
  std::printf("centrec thermal %s: %s %dx%d, T_in %.2f K -> T_out %.2f K (%.2f C), efficiency %s, mdot %.4g kg/s\n",
              c.path.c_str(), c.grid.lumped ? "1D" : "2D", r.op->grid().nz, r.op->grid().nxi, c.model.T_in, b.T_out,
              b.T_out - 273.15, runs::efficiency_text(b.efficiency).c_str(), b.mass_flow);
  std::printf(
      "  powers (W): incident %.6g, absorbed %.6g, emitted %.6g, convected %.6g, wall %.6g, carried %.6g; "
      "balance residual %.2e of %s\n",
      b.incident, b.absorbed, b.emitted, b.convected, b.wall, b.carried, b.residual / thermal::film_balance_scale(b),
      b.absorbed >= thermal::film_balance_scale(b) ? "absorbed" : "the film's largest power");
  runs::print_receiver_report(c, r);
  std::printf("  k_eff film mean %.4g W/(m K); steady solve %.3f s (%d Newton, %ld BDF steps)%s; total %.3f s\n",
              runs::section_mean(r.keff, &thermal::KeffSection::k_eff), r.steady_seconds, r.steady.newton_iterations,
              r.steady.stats.steps, r.has_transient ? ", transient run" : "", seconds);
  if (r.has_transient) {
    const runs::TransientOutlet o = runs::transient_outlet(r);
    std::printf("  transient to %.4g s: T_out %.2f -> %.2f K (min %.2f, max %.2f), %ld steps, %.3f s\n", o.t_end,
                o.T_start, o.T_end, o.T_min, o.T_max, r.transient.stats.steps, r.transient_seconds);
  }
  std::printf("  wrote %s/{thermal.h5,thermal.xmf,summary.json,along_z.csv}\n", out_dir.c_str());
  return 0;
}

}  // namespace centrec::cli
