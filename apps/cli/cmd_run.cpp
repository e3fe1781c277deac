// `centrec run CASE.yaml --out DIR`: the coupled DEM -> coupling -> thermal run.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "cli/case_overrides.hpp"
#include "cli/child_processes.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/plot_scripts.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/summary_json.hpp"
#include "runs/coupled_output.hpp"
#include "runs/coupled_run.hpp"
#include "runs/headline_figures.hpp"
#include "runs/interrupt.hpp"
#include "runs/provenance.hpp"
#include "runs/replica_summary.hpp"
#include "runs/thermal_output.hpp"

namespace centrec::cli {

namespace {
void print_run_help(const CommandLine& app) {
  std::printf("usage: centrec run CASE.yaml --out DIR [options]\n\n%s\n", app.options_text().c_str());
  std::printf(
      "The coupled run (docs/architecture.md): the DEM of the case's `dem:` drum or slice\n"
      "(derived from `receiver:` by eqs 1-3 when receiver.dem_diameter_d is given), run until\n"
      "its flow is steady; its film as measured (full-circumference profiles per section, up to\n"
      "where they carry 99.5 %% of the flow; film.mapping chooses another) handed to the thermal\n"
      "film, its flow checked against the DEM's measured flow (flux closure, 5 %%), scaled up\n"
      "to the receiver when the case has one, the case's mass flow imposed by one velocity\n"
      "factor, then the thermal model of `thermal:` (docs/coupling.md).\n"
      "Refused unless allowed: a DEM drum below D/d = 80, the scale-down laws' validity\n"
      "threshold (docs/validity_threshold.md; --allow-small-drum), and a DEM film that is not\n"
      "at steady flow or misses the flux closure (--allow-unsteady); allowed, they are\n"
      "warnings in the output and in summary.json \"warnings\".\n"
      "k_eff (summary.json k_eff) is the film's wall-normal effective conductivity over its\n"
      "moving part, t_m / sum(deta / k_n) with k_n = ZBS bed (with radiation) + mixing\n"
      "phi rho_s c_p D; its parts bed conduction, radiation and mixing add up to it\n"
      "(docs/thermal_model.md \"Effective conductivity\", also where ZBS is used outside\n"
      "its validity).\n"
      "The DEM outputs are cached in CACHE/<hash of every DEM input> (default: the parent of\n"
      "DIR + /dem-cache): a thermal-only change reruns in seconds. A case with `film: {file:}`\n"
      "skips the DEM; so does --dem-from DEM_DIR, the folder of a finished `centrec dem CASE`\n"
      "run of the same DEM inputs (the dem: and receiver: sections; the thread count may\n"
      "differ), whose dem.h5 gives the film (a mismatch is refused, naming the keys).\n"
      "--speed-rpm and --mass-flow replace the receiver's operating point (or\n"
      "the DEM drum's, without a receiver); `centrec sweep` uses them. --seed replaces\n"
      "dem.seed. --set KEY=VALUE sets any case key (thermal.flux.q_film=3e5, thermal.T_in=900):\n"
      "the value passes the key's own checks and the resolved configuration in the outputs holds it.\n"
      "--replicas N runs the whole chain N times, with DEM seeds dem.seed, dem.seed + 1, ...,\n"
      "into DIR/replica_<k>/ (as many at a time as there are threads, the threads shared out),\n"
      "and writes DIR/summary.json with the mean and standard deviation over the seeds of T_out,\n"
      "efficiency, k_eff and its parts, film thickness and flux closure (\"replicas\"). A replica\n"
      "that fails (its film refused, say) is named with its reason (\"replicas\": \"failed\", and a\n"
      "warning); the spread is then over the others when two or more finished, and the exit\n"
      "status is 1.\n\n"
      "Writes DIR/summary.json (outlet temperature, efficiency, k_eff and its parts, film\n"
      "thickness, mdot, scaling, wall time per stage), DIR/results.h5 (thermal fields, /film,\n"
      "/coupling), DIR/results.xmf (the temperature field for ParaView), DIR/film.h5 (the film\n"
      "field; reusable as `film: {file: DIR/film.h5}`) and the figures of apps/plot_run.py:\n"
      "the paper's Figs 2, 3 and 6 from the DEM (fig2_mass_flow.png, fig3_film_thickness.png,\n"
      "fig6_velocity_profiles.png), the film temperature field (thermal_T_map.png), the power\n"
      "balance (losses.png), k_eff, film and velocity (--no-plots: none; --figures png,pdf,svg and\n"
      "--dpi N: other formats and resolutions).\n");
}

std::string parent_of(const std::string& dir) {
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  const std::size_t slash = d.rfind('/');
  return slash == std::string::npos ? "." : d.substr(0, slash);
}
// `--replicas N`: the same command N times as child processes, seed base + k into
// DIR/replica_<k>/, then the spread of the headline figures (runs/replica_summary.hpp).
int run_replicas(const CommandLine& app, const Args& args, const std::string& case_path, const std::string& out_dir,
                 const config::CaseFile& cf, const runs::RunOptions& o, int replicas, const FigureOptions& figures, bool overwrite) {
  if (!(cf.dem && cf.thermal && cf.thermal->film_source.from_dem()))
    throw UsageError(case_path + ": --replicas repeats the DEM with other seeds, but this case has no DEM film");
  // `cf` holds the overrides' keys: its seed and threads are the command line's when given.
  const long long base = static_cast<long long>(cf.dem->scene.seed);
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = o.overrides.sets("dem.run.threads") && cf.dem->scene.threads > 0 ? cf.dem->scene.threads : cores;
  const int parallel = std::min(replicas, threads);
  const int per_child = std::max(1, threads / parallel);
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec run --replicas " + case_path, folder_use(overwrite));
  // The command as given, minus the options this sets per replica (the override flags are
  // given anew from the overrides; --overwrite is passed on: the replicas' folders are the
  // earlier run's too).
  std::vector<std::string> set_here = override_flag_names();
  set_here.insert(set_here.end(), {"--out", "--replicas", "--cache", "--no-plots", "--figures", "--dpi"});
  const Args common = without_options(app, args, set_here);
  const std::string exe = own_executable();
  std::vector<ChildJob> jobs;
  std::vector<std::uint64_t> seeds;
  std::vector<std::string> dirs;
  for (int k = 0; k < replicas; ++k) {
    const std::string dir = out_dir + "/replica_" + std::to_string(k);
    io::ensure_directory(dir);
    ChildJob job{{exe, "run"}, dir + "/run.log"};
    job.argv.insert(job.argv.end(), common.begin(), common.end());
    job.argv.insert(job.argv.end(), {"--out", dir, "--cache", o.cache_dir});
    config::Overrides replica = o.overrides;
    replica.keys["dem.seed"] = std::to_string(base + k);
    replica.keys["dem.run.threads"] = std::to_string(per_child);
    const Args flags = override_args(replica, "run");
    job.argv.insert(job.argv.end(), flags.begin(), flags.end());
    FigureOptions replica_figures = figures;
    replica_figures.none = figures.none || k > 0;  // replica 0 draws the figures
    const Args figure_flags = figure_args(replica_figures);
    job.argv.insert(job.argv.end(), figure_flags.begin(), figure_flags.end());
    jobs.push_back(job);
    seeds.push_back(static_cast<std::uint64_t>(base + k));
    dirs.push_back(dir);
  }
  std::printf("centrec run %s: %d replicas (seeds %lld-%lld), %d at a time with %d DEM thread(s) each\n",
              case_path.c_str(), replicas, base, base + replicas - 1, parallel, per_child);
  std::fflush(stdout);
  const int failed = run_child_jobs(jobs, parallel, nullptr, [&](std::size_t k) {
    std::printf("  replica %zu (seed %llu): %s\n", k, static_cast<unsigned long long>(seeds[k]),
                jobs[k].status == 0
                    ? "done"
                    : ("FAILED (exit " + std::to_string(jobs[k].status) + "), see " + jobs[k].log).c_str());
    std::fflush(stdout);
  });
  // A replica that failed (a seed whose film is refused, say) is named with its reason; the
  // spread is then over the others, when there are two or more, and the exit status says so.
  std::vector<nlohmann::json> summaries;
  std::vector<std::uint64_t> done_seeds;
  std::vector<std::string> done_dirs;
  nlohmann::json failures = nlohmann::json::array();
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    if (jobs[k].status == 0) {
      summaries.push_back(io::read_json_file(dirs[k] + "/summary.json"));
      done_seeds.push_back(seeds[k]);
      done_dirs.push_back(dirs[k]);
    } else {
      failures.push_back(
          {{"seed", seeds[k]}, {"dir", dirs[k]}, {"exit", jobs[k].status}, {"reason", failure_reason(jobs[k])}});
    }
  }
  if (failed)
    std::fprintf(stderr, "centrec run: %d of %d replicas failed; the others are in %s/replica_*\n", failed, replicas,
                 out_dir.c_str());
  if (summaries.size() < 2) return failed ? 1 : 0;
  nlohmann::json s = runs::combine_replicas(summaries, done_seeds, done_dirs);
  if (failed) {
    s["replicas"]["failed"] = failures;
    for (const auto& f : failures)
      s["warnings"].push_back("replica of seed " + std::to_string(f["seed"].get<std::uint64_t>()) +
                              " failed and is left out of the spread: " + f["reason"].get<std::string>());
  }
  io::write_json_file(out_dir + "/summary.json", s);
  std::printf("centrec run %s: mean +- standard deviation over %zu DEM seeds%s (%s/summary.json \"replicas\")\n",
              case_path.c_str(), summaries.size(),
              failed ? (" of " + std::to_string(replicas) + ": the failed ones left out").c_str() : "", out_dir.c_str());
  for (const runs::HeadlineFigure& fig : runs::headline_figures()) {
    const auto& f = s["replicas"]["figures"][fig.pointer];
    std::printf("  %-34s %.6g +- %.3g %s\n", fig.pointer.c_str() + 1, f["mean"].get<double>(), f["std"].get<double>(),
                fig.unit == "-" ? "" : fig.unit.c_str());
  }
  for (const auto& w : s["warnings"]) std::printf("  WARNING: %s\n", w.get<std::string>().c_str());
  return failed ? 1 : 0;
}
}  // namespace

int cmd_run(const Args& args) {
  std::string case_path, out_dir;
  runs::RunOptions o;
  bool overwrite = false;
  FigureOptions figures;
  int replicas = 1;
  CommandLine app("run");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir, "the run's folder (created)")->required()->option_text("DIR");
  add_override_flags(app, o.overrides, "run");
  app.add_option("--replicas", replicas, "run the chain with N DEM seeds (seed, seed + 1, ...) and their spread")
      ->check(integer_in(1, 64))
      ->option_text("N");
  add_figure_flags(app, figures);
  add_overwrite_flag(app, overwrite);
  for (const runs::RunOptionFlag& f : runs::run_option_flags()) {
    if (f.on)
      app.add_flag(f.name, o.*f.on, f.help);
    else
      app.add_option(f.name, o.*f.text, f.help)->option_text(f.value_name);
  }
  if (wants_help(args)) {
    print_run_help(app);
    return 0;
  }
  app.read(args);
  if (o.cache_dir.empty()) o.cache_dir = parent_of(out_dir) + "/dem-cache";
  const config::Overrides& overrides = o.overrides;
  const config::CaseFile given = config::read_case_file(case_path);
  runs::check_run_options(given, o);
  if (given.thermal && !given.thermal->film_source.from_dem())
    for (const char* flag : {"--cache", "--allow-small-drum", "--allow-unsteady"})
      if (app.count(flag))
        throw UsageError(std::string(flag) + " concerns the DEM, but " + case_path + " takes its film from " +
                         given.thermal->film_source.text() + " (no DEM runs)");
  const config::CaseFile cf = checked_overrides(given, overrides, "run");
  if (cf.dem && cf.thermal && cf.thermal->film_source.from_dem()) checked_dem(cf, overrides, "run");
  if (replicas > 1 && !o.dem_from.empty())
    throw UsageError("--replicas runs the DEM with other seeds; --dem-from takes one earlier run: give one of them");
  if (replicas > 1) return run_replicas(app, args, case_path, out_dir, cf, o, replicas, figures, overwrite);
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec run " + case_path, folder_use(overwrite));
  runs::CoupledRun r;
  try {
    r = runs::run_coupled_case(cf, o);
  } catch (const runs::RunInterrupted& e) {
    std::fprintf(stderr, "centrec run: %s\n  continue with the same command: its DEM resumes from that checkpoint\n",
                 e.what());
    return 128 + e.signal();
  } catch (const runs::OutputsInterrupted& e) {
    std::fprintf(stderr, "centrec run: the DEM's %s; the thermal stage was not run\n  continue with the same command\n",
                 e.what());
    return 128 + e.signal();
  }
  runs::write_coupled_h5(out_dir, r, runs::case_provenance(cf.path, cf.resolved_yaml));
  nlohmann::json s = runs::coupled_summary(r);
  s["resolved_config"] = cf.resolved_yaml;
  if (!flags_text(overrides, "run").empty()) s["command_line_overrides"] = flags_text(overrides, "run");
  io::write_json_file(out_dir + "/summary.json", s);

  const auto& b = r.result.balance;
  std::printf("centrec run %s\n", case_path.c_str());
  if (r.film_from_dem()) {
    const auto& sd = r.dem.scene;
    const char* source = r.dem_given ? "from an earlier run" : r.dem_cached ? "from cache" : "run";
    std::printf("  DEM %s (%s): %s D = %.4g m (D/d %.0f), %.2f rpm\n", source, r.dem_dir.c_str(),
                sd.slice.enabled ? "slice of the drum" : "drum", sd.drum.diameter,
                sd.drum.diameter / sd.particle.diameter, coupling::rad_per_s_to_rpm(sd.drum.omega));
    std::printf("  DEM steady state: %s\n", r.averages.steady_text.c_str());
    std::printf(
        "  film (%s mapping): %.2f d thick %s; eqs 4-7 thickness %.2f d; moving zone %.0f %% of the "
        "circumference\n",
        r.mapping.mapping.c_str(), runs::film_thickness(r).mean_d, r.mapping.text.c_str(),
        r.dem_summary.value("mean_film_thickness_d", 0.0), 100.0 * r.averages.moving_fraction);
    std::printf(
        "  flux closure: the film carries %.1f %% of the measured %.4g g/s (sections %.1f-%.1f %%, tolerance "
        "%.0f %%)\n",
        100.0 * r.closure.mean_over_measured, r.averages.mdot * 1e3, 100.0 * r.closure.min_over_measured,
        100.0 * r.closure.max_over_measured, 100.0 * coupling::kFlowClosureTolerance);
  }
  if (r.has_receiver)
    std::printf("  scaled up to the receiver D = %.4g m, L = %.4g m, %.2f rpm: z x %.4g\n", r.receiver.op.diameter,
                r.receiver.op.length, coupling::rad_per_s_to_rpm(r.receiver.op.omega), r.scale.length_ratio);
  if (r.film_from_dem())
    std::printf("  imposed the case's %.4g kg/s with one velocity factor %.4f\n", r.imposed.mdot, r.imposed.factor);
  for (const auto& w : r.warnings) std::printf("  WARNING: %s\n", w.c_str());
  std::printf("  outlet temperature %.2f K (%.2f C) from %.2f K, efficiency %.4f, mdot %.4g kg/s\n", b.T_out,
              b.T_out - 273.15, r.thermal.model.T_in, b.efficiency, b.mass_flow);
  runs::print_receiver_report(r.thermal, r.result);
  const auto k_mean = [&](double thermal::KeffSection::*m) { return runs::section_mean(r.result.keff, m); };
  std::printf("  k_eff %.4g W/(m K) = bed %.4g + radiation %.4g + mixing %.4g\n", k_mean(&thermal::KeffSection::k_eff),
              k_mean(&thermal::KeffSection::bed_conduction), k_mean(&thermal::KeffSection::radiation),
              k_mean(&thermal::KeffSection::mixing));
  std::printf(
      "  wall time: DEM %.1f s, coupling %.3f s, thermal %.3f s; wrote "
      "%s/{summary.json,results.h5,results.xmf,film.h5,along_z.csv,film_profiles.csv}\n",
      r.dem_seconds, r.mapping_seconds, r.thermal_seconds, out_dir.c_str());
  std::vector<std::string> plot_args = {out_dir};
  if (r.film_from_dem()) plot_args.insert(plot_args.end(), {"--dem", r.dem_dir});
  run_plot_script("centrec run", "plot_run.py", plot_args, figures);
  return 0;
}

}  // namespace centrec::cli
