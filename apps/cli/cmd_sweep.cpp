// `centrec sweep CASE.yaml --out DIR`: the operating map. Runs `centrec
// run` over the case's sweep grid (speed x mass flow) as parallel processes, then tabulates
// outlet temperature, efficiency and k_eff (DIR/sweep.csv, DIR/sweep.json) and charts them
// (apps/plot_sweep.py).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "cli/case_overrides.hpp"
#include "cli/child_processes.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/plot_scripts.hpp"
#include "config/case_file.hpp"
#include "config/case_receiver.hpp"
#include "coupling/scaling_laws.hpp"
#include "io/atomic_write.hpp"
#include "io/summary_json.hpp"
#include "runs/headline_figures.hpp"

namespace centrec::cli {

namespace {
struct Point {
  double rpm = 0.0, mdot = 0.0;
  std::string dir;
  int status = -1;
};

void print_sweep_help(const CommandLine& app) {
  std::printf("usage: centrec sweep CASE.yaml --out DIR [options]\n\n%s\n", app.options_text().c_str());
  std::printf(
      "Runs the coupled `centrec run` for every point of the case's `sweep:` grid\n"
      "(speed_rpm x mass_flow: the receiver's operating point, or the DEM drum's without a\n"
      "receiver), N processes at a time (sweep.parallel, one DEM thread each), each into\n"
      "DIR/rpm<N>_mdot<M>/ with its log in run.log. Then writes DIR/sweep.csv and\n"
      "DIR/sweep.json (outlet temperature, efficiency, k_eff and its parts, film thickness per\n"
      "point) and the charts of apps/plot_sweep.py (DIR/sweep_*.png). --replicas N runs each\n"
      "point with N DEM seeds (`centrec run --replicas`) and adds each figure's standard\n"
      "deviation over the seeds (*_std columns).\n");
}

// The `centrec run` of one point, its stdout/stderr in DIR/run.log: the point's speed and
// flow and one DEM thread as the override flags write them (cli/case_overrides.hpp). Every
// point runs with --allow-unsteady: a point whose DEM did not reach steady flow is reported
// as such in the table rather than lost.
ChildJob point_job(const std::string& exe, const std::string& case_path, const std::string& cache, const Point& p,
                   const config::Overrides& given, bool allow_small_drum, int replicas, bool overwrite) {
  io::ensure_directory(p.dir);
  config::Overrides o = given;
  o.speed_rpm = p.rpm;
  o.mass_flow = p.mdot;
  o.keys["dem.run.threads"] = "1";
  ChildJob job{{exe, "run", case_path, "--out", p.dir, "--cache", cache}, p.dir + "/run.log"};
  const Args flags = override_args(o);
  job.argv.insert(job.argv.end(), flags.begin(), flags.end());
  job.argv.insert(job.argv.end(), {"--no-plots", "--allow-unsteady"});
  if (allow_small_drum) job.argv.push_back("--allow-small-drum");
  if (overwrite) job.argv.push_back("--overwrite");
  if (replicas > 1) job.argv.insert(job.argv.end(), {"--replicas", std::to_string(replicas)});
  return job;
}

// The point's speed and flow as the override flags write them (each reads back as itself):
// two different points never share a folder name.
std::string point_name(double rpm, double mdot) {
  config::Overrides o;
  o.speed_rpm = rpm;
  o.mass_flow = mdot;
  const Args a = override_args(o);  // {"--speed-rpm", rpm, "--mass-flow", mdot}
  return "rpm" + a[1] + "_mdot" + a[3];
}
}  // namespace

int cmd_sweep(const Args& args) {
  std::string case_path, out_dir, cache;
  int parallel = 0, replicas = 1;
  bool allow_small_drum = false, overwrite = false;
  CommandLine app("sweep");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir, "the sweep's folder (created)")->required()->option_text("DIR");
  app.add_option("--cache", cache, "the DEM cache (default: DIR/dem-cache)")->option_text("DIR");
  app.add_option("--parallel", parallel, "points run at a time (default sweep.parallel)")
      ->check(integer_in(1, 1024))
      ->option_text("N");
  app.add_option("--replicas", replicas, "DEM seeds per point (`centrec run --replicas`)")
      ->check(integer_in(1, 64))
      ->option_text("N");
  app.add_flag("--allow-small-drum", allow_small_drum,
               "run a DEM drum below the scale-down validity threshold (the outputs carry a warning)");
  add_overwrite_flag(app, overwrite);
  config::Overrides overrides;  // --set: the same at every point
  add_override_flags(app, overrides, "sweep");
  if (wants_help(args)) {
    print_sweep_help(app);
    return 0;
  }
  app.read(args);
  const config::CaseFile cf = checked_overrides(config::read_case_file(case_path), overrides);
  if (!cf.sweep) throw std::invalid_argument(case_path + " has no `sweep:` section (speed_rpm, mass_flow lists)");
  if (cf.dem) {  // the drum's size does not depend on the swept speed and flow
    config::DemCase dem = *cf.dem;
    if (cf.receiver) config::apply_receiver(*cf.receiver, dem, false);
    const std::string small = coupling::scale_down_validity(dem.scene.drum.diameter, dem.scene.particle.diameter);
    if (!small.empty() && !allow_small_drum)
      throw std::invalid_argument(case_path + ": " + small + "; --allow-small-drum runs it anyway (with a warning)");
  }
  if (parallel <= 0) parallel = cf.sweep->parallel;
  if (cache.empty()) cache = out_dir + "/dem-cache";
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec sweep " + case_path, folder_use(overwrite));
  const std::string exe = own_executable();

  std::vector<Point> points;
  for (double rpm : cf.sweep->speed_rpm)
    for (double mdot : cf.sweep->mass_flow) points.push_back({rpm, mdot, out_dir + "/" + point_name(rpm, mdot)});
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (points[k].dir == points[i].dir)
        throw std::invalid_argument(case_path + ": the sweep grid lists the point " + point_name(points[i].rpm, points[i].mdot) +
                                    " twice (a speed or a mass flow repeated)");
  std::vector<ChildJob> jobs;
  for (const Point& p : points) jobs.push_back(point_job(exe, case_path, cache, p, overrides, allow_small_drum, replicas, overwrite));
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  run_child_jobs(
      jobs, parallel,
      [&](std::size_t k) {
        std::printf("  started %s\n", points[k].dir.c_str());
        std::fflush(stdout);
      },
      [&](std::size_t k) {
        Point& p = points[k];
        p.status = jobs[k].status;
        const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("  [%zu/%zu] %s: %s (%.0f s)\n", ++done, points.size(), p.dir.c_str(),
                    p.status == 0 ? "done" : "FAILED, see run.log", el);
        std::fflush(stdout);
      });

  // Table of the headline figures (runs/headline_figures.hpp), read from each point's summary.json.
  const auto& figures = runs::headline_figures();
  nlohmann::json table = nlohmann::json::array();
  std::ostringstream csv;
  csv << "speed_rpm,mass_flow_kg_s";
  for (const auto& f : figures) csv << ',' << f.column;
  csv << ",dem_flow";
  if (replicas > 1) {
    for (const auto& f : figures) csv << ',' << f.column << "_std";
    csv << ",replicas";
  }
  csv << '\n';
  int failed = 0;
  for (const Point& p : points) {
    nlohmann::json row = {{"speed_rpm", p.rpm}, {"mass_flow_kg_s", p.mdot}, {"dir", p.dir}, {"status", p.status}};
    csv << p.rpm << ',' << p.mdot;
    if (p.status != 0) {
      ++failed;
      csv << std::string(figures.size(), ',') << ",failed";
      if (replicas > 1) csv << std::string(figures.size() + 1, ',');
      csv << '\n';
      table.push_back(row);
      continue;
    }
    const nlohmann::json s = io::read_json_file(p.dir + "/summary.json");
    for (const auto& f : figures) {
      double v = 0.0;
      csv << ',';
      if (!runs::headline_value(s, f, v)) continue;  // an empty cell: the point has no such figure
      row[f.column] = v;
      csv << v;
    }
    const bool steady = s.contains("dem") && s["dem"].value("steady", false);
    row["dem_flow"] = s.contains("dem") ? s["dem"].value("steady_state", "") : "";
    row["dem_flow_steady"] = steady;
    row["warnings"] = s.value("warnings", nlohmann::json::array());
    csv << ',' << (steady ? "steady" : "NOT steady");
    if (replicas > 1) {
      const auto& spread = s["replicas"]["figures"];
      for (const auto& f : figures) {
        csv << ',';
        if (spread.contains(f.pointer)) csv << spread[f.pointer]["std"].get<double>();
      }
      row["replicas"] = s["replicas"];
      csv << ',' << s["replicas"]["count"].get<int>();
    }
    csv << '\n';
    table.push_back(row);
  }
  io::write_text_atomically(out_dir + "/sweep.csv", csv.str());
  io::write_json_file(out_dir + "/sweep.json", {{"case", case_path}, {"points", table}});
  std::printf("centrec sweep %s: %zu points, %d failed; wrote %s/sweep.csv and sweep.json\n", case_path.c_str(),
              points.size(), failed, out_dir.c_str());
  std::fputs(csv.str().c_str(), stdout);
  run_plot_script("centrec sweep", "plot_sweep.py", {out_dir});
  return failed ? 1 : 0;
}

}  // namespace centrec::cli
