// `centrec run CASE.yaml --out DIR`: the coupled DEM -> coupling -> thermal run.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/summary_json.hpp"
#include "runs/coupled_output.hpp"
#include "runs/coupled_run.hpp"
#include "runs/interrupt.hpp"
#include "runs/thermal_output.hpp"

namespace centrec::cli {

namespace {
void print_run_help() {
  std::printf(
      "usage: centrec run CASE.yaml --out DIR [--cache DIR] [--speed-rpm N] [--mass-flow KG_S]\n"
      "                  [--threads N] [--no-plots]\n\n"
      "The coupled run (docs/architecture.md): the DEM of the case's `dem:` drum (derived from\n"
      "`receiver:` by eqs 1-3 when receiver.dem_diameter_d is given), its averaged film fields\n"
      "mapped onto the thermal film (tangential average, mass flux conserved), scaled up to the\n"
      "receiver when the case has one, then the thermal model of `thermal:`.\n"
      "The DEM outputs are cached in CACHE/<hash of every DEM input> (default: the parent of\n"
      "DIR + /dem-cache): a thermal-only change reruns in seconds. A case with `film: {file:}`\n"
      "skips the DEM. --speed-rpm and --mass-flow replace the receiver's operating point (or\n"
      "the DEM drum's, without a receiver); `centrec sweep` uses them.\n\n"
      "Writes DIR/summary.json (outlet temperature, efficiency, k_eff and its parts, film\n"
      "thickness, mdot, scaling, wall time per stage), DIR/results.h5 (thermal fields, /film,\n"
      "/coupling), DIR/film.h5 (the film field; reusable as `film: {file: DIR/film.h5}`) and\n"
      "the PNGs of apps/plot_run.py (film, velocity, temperature map, k_eff along z).\n");
}

std::string ratios(const std::vector<double>& v) {
  std::string out;
  char b[32];
  for (double x : v) {
    std::snprintf(b, sizeof b, "%s%.3f", out.empty() ? "" : "/", x);
    out += b;
  }
  return out;
}

std::string parent_of(const std::string& dir) {
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  const std::size_t slash = d.rfind('/');
  return slash == std::string::npos ? "." : d.substr(0, slash);
}
}  // namespace

int cmd_run(const Args& args) {
  if (wants_help(args)) {
    print_run_help();
    return 0;
  }
  std::string case_path, out_dir;
  runs::RunOptions o;
  bool no_plots = false;
  CommandLine app("run");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir)->required();
  app.add_option("--cache", o.cache_dir);
  // The ranges of receiver.speed_rpm and receiver.mass_flow (config/case_receiver.cpp).
  app.add_option("--speed-rpm", o.speed_rpm)->check(number_in(config::Range::open_closed(0.0, 1e5), "rpm"));
  app.add_option("--mass-flow", o.mass_flow)->check(number_in(config::Range::open_closed(0.0, 1e4), "kg/s"));
  app.add_option("--threads", o.threads)->check(integer_in(0, 1024));
  app.add_flag("--no-plots", no_plots);
  app.read(args);
  const bool plots = !no_plots;
  if (o.cache_dir.empty()) o.cache_dir = parent_of(out_dir) + "/dem-cache";
  const config::CaseFile cf = config::read_case_file(case_path);
  const config::Overrides overrides = runs::run_overrides(o);
  if (cf.dem && cf.thermal && cf.thermal->film_source == "dem") checked_dem(cf, overrides);
  const io::OutputFolder out(out_dir);
  runs::CoupledRun r;
  try {
    r = runs::run_coupled_case(cf, o);
  } catch (const runs::RunInterrupted& e) {
    std::fprintf(stderr, "centrec run: %s\n  continue with the same command: its DEM resumes from that checkpoint\n",
                 e.what());
    return 128 + e.signal();
  }
  runs::write_coupled_h5(out_dir, r);
  nlohmann::json s = runs::coupled_summary(r);
  s["resolved_config"] = cf.resolved_yaml;
  if (!flags_text(overrides).empty()) s["command_line_overrides"] = flags_text(overrides);
  io::write_json_file(out_dir + "/summary.json", s);

  const auto& b = r.result.balance;
  const auto& k = s["k_eff"]["film_mean"];
  std::printf("centrec run %s\n", case_path.c_str());
  if (r.film_from_dem)
    std::printf("  DEM %s (%s): D = %.4g m, %.2f rpm, outlet %.4g g/s; film %.2f d thick (%.2f-%.2f d)\n",
                r.dem_cached ? "from cache" : "run", r.dem_dir.c_str(), r.dem.scene.drum.diameter,
                coupling::rad_per_s_to_rpm(r.dem.scene.drum.omega), r.averages.mdot * 1e3,
                s["film"]["mean_thickness_d"].get<double>(), s["film"]["min_thickness_d"].get<double>(),
                s["film"]["max_thickness_d"].get<double>());
  if (r.has_receiver)
    std::printf("  scaled up to the receiver D = %.4g m, L = %.4g m, %.2f rpm: z x %.4g, mdot %.4g kg/s\n",
                r.receiver.op.diameter, r.receiver.op.length, coupling::rad_per_s_to_rpm(r.receiver.op.omega),
                r.scale.length_ratio, r.conservation.mdot);
  if (r.film_from_dem)
    std::printf("  mass flux: DEM profiles (all bins) / DEM outlet %s; within t %.3f-%.3f; imposed %.4g kg/s, "
                "cylindrical error %.2e\n",
                ratios(r.tangential.profile_flux_over_mdot).c_str(),
                s["coupling"]["sampled_flux_over_mdot_min"].get<double>(),
                s["coupling"]["sampled_flux_over_mdot_max"].get<double>(), r.conservation.mdot,
                r.conservation.max_cylindrical_error);
  std::printf("  outlet temperature %.2f K (%.2f C) from %.2f K, efficiency %.4f, mdot %.4g kg/s\n", b.T_out,
              b.T_out - 273.15, r.thermal.model.T_in, b.efficiency, b.mass_flow);
  runs::print_receiver_report(r.thermal, b);
  std::printf("  k_eff %.4g W/(m K) = bed %.4g + radiation %.4g + mixing %.4g\n", k["k_eff"].get<double>(),
              k["bed_conduction"].get<double>(), k["radiation"].get<double>(), k["mixing"].get<double>());
  std::printf("  wall time: DEM %.1f s, coupling %.3f s, thermal %.3f s; wrote %s/{summary.json,results.h5,film.h5}\n",
              r.dem_seconds, r.mapping_seconds, r.thermal_seconds, out_dir.c_str());
  if (plots) {
    const std::string cmd = "/usr/bin/python3 " CENTREC_PLOT_DIR "/plot_run.py '" + out_dir + "'";
    if (std::system(cmd.c_str()) != 0)
      std::fprintf(stderr, "centrec run: plotting failed (needs python3-matplotlib, python3-h5py): %s\n", cmd.c_str());
  }
  return 0;
}

}  // namespace centrec::cli
