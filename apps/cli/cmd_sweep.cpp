// `centrec sweep CASE.yaml --out DIR`: a parameter study. Runs `centrec run` over a grid of
// case keys (cli/sweep_grid.hpp; by default the case's speed x mass flow) as parallel
// processes, then tabulates the inputs of each point and its outlet temperature, efficiency
// and k_eff (DIR/sweep.csv, DIR/sweep.json) and charts them (apps/plot_sweep.py).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <set>
#include <stdexcept>
#include <utility>

#include "cli/case_overrides.hpp"
#include "cli/child_processes.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/plot_scripts.hpp"
#include "cli/sweep_grid.hpp"
#include "config/case_file.hpp"
#include "config/case_receiver.hpp"
#include "coupling/scaling_laws.hpp"
#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
#include "io/summary_json.hpp"
#include "runs/dem_cache.hpp"
#include "runs/headline_figures.hpp"

namespace centrec::cli {

namespace {
void print_sweep_help(const CommandLine& app) {
  std::printf("usage: centrec sweep CASE.yaml --out DIR [--grid KEY=v1,v2,...]... [options]\n\n%s\n",
              app.options_text().c_str());
  std::printf(
      "Runs the coupled `centrec run` for every point of a grid, N processes at a time\n"
      "(--parallel or sweep.parallel, one DEM thread each), each into DIR/<point>/ with its log\n"
      "in run.log. The grid: --grid KEY=v1,v2,... (repeatable: the Cartesian product), or\n"
      "--points FILE.csv (a header of keys, a row of values per point), or else the case's\n"
      "`sweep:` section (speed_rpm x mass_flow). KEY is any case key as its dotted path\n"
      "(thermal.flux.q_film, thermal.T_in, dem.seed, ...), each value checked by the key's own\n"
      "reader before any point starts, or the operating point: speed_rpm (rpm) and mass_flow\n"
      "(kg/s), the receiver's or, without one, the DEM drum's. Points that share their DEM (a\n"
      "thermal-only change) run it once: the first of each DEM runs first, the rest reuse it\n"
      "from the cache. Then writes DIR/sweep.csv and DIR/sweep.json (the swept keys, the inputs\n"
      "that define each point: speed, mass flow, T_in, mean flux, seed, dt; outlet temperature,\n"
      "efficiency, k_eff and its parts, film thickness) and the charts of apps/plot_sweep.py\n"
      "(DIR/sweep_*.png). --replicas N runs each point with N DEM seeds (`centrec run\n"
      "--replicas`) and adds each figure's standard deviation over the seeds (*_std columns).\n");
}

// The `centrec run` of one point, its stdout/stderr in DIR/run.log: the point's values and,
// for a DEM film, one DEM thread as the override flags write them (cli/case_overrides.hpp).
// Every DEM point runs with --allow-unsteady: a point whose DEM did not reach steady flow is
// reported as such in the table rather than lost.
ChildJob point_job(const std::string& exe, const std::string& case_path, const std::string& cache,
                   const std::string& dir, config::Overrides o, bool has_dem, bool allow_small_drum, int replicas,
                   bool overwrite) {
  io::ensure_directory(dir);
  ChildJob job{{exe, "run", case_path, "--out", dir, "--no-plots"}, dir + "/run.log"};
  if (has_dem) {  // a DEM film: one thread, the sweep's cache
    o.keys["dem.run.threads"] = "1";
    job.argv.insert(job.argv.end(), {"--cache", cache, "--allow-unsteady"});
    if (allow_small_drum) job.argv.push_back("--allow-small-drum");
  }
  const Args flags = override_args(o, "run");
  job.argv.insert(job.argv.end(), flags.begin(), flags.end());
  if (overwrite) job.argv.push_back("--overwrite");
  if (replicas > 1) job.argv.insert(job.argv.end(), {"--replicas", std::to_string(replicas)});
  return job;
}

// The DEM cache key a point's run will look up, or "" when its film does not come from a
// DEM: points with one key share one DEM run.
std::string point_dem_key(const config::CaseFile& cf, const SweepPoint& p) {
  if (!cf.dem || (cf.thermal && !cf.thermal->film_source.from_dem())) return "";
  config::Overrides o = p.overrides;
  o.keys["dem.run.threads"] = "1";
  const config::CaseFile point = checked_overrides(cf, o, "run");
  return runs::dem_cache_key(point.resolved_yaml, checked_dem(point, o, "run"), io::code_version());
}

// A point's swept value in sweep.json: a number when it reads as one.
nlohmann::json value_json(const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (!v.empty() && end && *end == '\0') return x;
  return v;
}

std::string csv_cell(const std::string& v) {
  if (v.find_first_of(",\"\n") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
}  // namespace

int cmd_sweep(const Args& args) {
  std::string case_path, out_dir, cache, points_csv;
  std::vector<std::string> grid_flags;
  int parallel = 0, replicas = 1;
  bool allow_small_drum = false, overwrite = false;
  CommandLine app("sweep");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir, "the sweep's folder (created)")->required()->option_text("DIR");
  app.add_option("--grid", grid_flags,
                 "a swept key and its values (KEY=v1,v2,...); repeatable: the points are the Cartesian product")
      ->option_text("KEY=V1,V2")
      ->allow_extra_args(false);
  app.add_option("--points", points_csv, "the points as a CSV: a header of keys, one row of values per point")
      ->option_text("FILE");
  app.add_option("--cache", cache, "the DEM cache (default: DIR/dem-cache)")->option_text("DIR");
  app.add_option("--parallel", parallel, "points run at a time (default sweep.parallel, else 2)")
      ->check(integer_in(1, 1024))
      ->option_text("N");
  app.add_option("--replicas", replicas, "DEM seeds per point (`centrec run --replicas`)")
      ->check(integer_in(1, 64))
      ->option_text("N");
  app.add_flag("--allow-small-drum", allow_small_drum,
               "run a DEM drum below the scale-down validity threshold (the outputs carry a warning)");
  add_overwrite_flag(app, overwrite);
  FigureOptions charts;  // the sweep's own charts (its points draw none)
  add_figure_flags(app, charts);
  config::Overrides overrides;  // --set: the same at every point
  add_override_flags(app, overrides, "sweep");
  if (wants_help(args)) {
    print_sweep_help(app);
    return 0;
  }
  app.read(args);
  if (!grid_flags.empty() && !points_csv.empty()) throw UsageError("give --grid or --points, not both");
  const config::CaseFile cf = checked_overrides(config::read_case_file(case_path), overrides, "sweep");
  SweepGrid grid;
  if (!points_csv.empty()) {
    grid = points_from_csv(points_csv, overrides);
  } else if (!grid_flags.empty()) {
    std::vector<std::pair<SweepAxis, std::vector<std::string>>> axes;
    for (const std::string& g : grid_flags) axes.push_back(parse_grid_flag(g));
    grid = cartesian_grid(axes, overrides);
  } else {
    if (!cf.sweep)
      throw UsageError(case_path + " has no `sweep:` section (speed_rpm, mass_flow lists); give the points with "
                       "--grid KEY=v1,v2,... or --points FILE.csv");
    std::vector<std::string> speeds, flows;
    for (double v : cf.sweep->speed_rpm) speeds.push_back(shortest_text(v));
    for (double v : cf.sweep->mass_flow) flows.push_back(shortest_text(v));
    grid = cartesian_grid({{sweep_axis("speed_rpm"), speeds}, {sweep_axis("mass_flow"), flows}}, overrides);
  }
  if (cf.dem) {  // the drum's size does not depend on the swept speed and flow
    config::DemCase dem = *cf.dem;
    if (cf.receiver) config::apply_receiver(*cf.receiver, dem, false);
    const std::string small = coupling::scale_down_validity(dem.scene.drum.diameter, dem.scene.particle.diameter);
    if (!small.empty() && !allow_small_drum)
      throw std::invalid_argument(case_path + ": " + small + "; --allow-small-drum runs it anyway (with a warning)");
  }
  check_sweep_points(cf, grid);
  if (parallel <= 0) parallel = cf.sweep ? cf.sweep->parallel : 2;
  if (cache.empty()) cache = out_dir + "/dem-cache";
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec sweep " + case_path, folder_use(overwrite));
  const std::string exe = own_executable();

  // The first point of each DEM runs first; the points that share it follow and read it
  // from the cache (two points starting one DEM at once would both run it).
  const bool dem_film = cf.dem && !(cf.thermal && !cf.thermal->film_source.from_dem());
  const std::size_t n = grid.points.size();
  std::vector<std::string> dirs(n);
  std::vector<int> status(n, -1);
  std::vector<std::size_t> first, after;
  std::set<std::string> keys;
  for (std::size_t k = 0; k < n; ++k) {
    dirs[k] = out_dir + "/" + grid.points[k].name;
    const std::string key = point_dem_key(cf, grid.points[k]);
    (key.empty() || keys.insert(key).second ? first : after).push_back(k);
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  for (const std::vector<std::size_t>* phase : {&first, &after}) {
    std::vector<ChildJob> jobs;
    for (std::size_t k : *phase)
      jobs.push_back(point_job(exe, case_path, cache, dirs[k], grid.points[k].overrides, dem_film, allow_small_drum,
                               replicas, overwrite));
    run_child_jobs(
        jobs, parallel,
        [&](std::size_t j) {
          std::printf("  started %s\n", dirs[(*phase)[j]].c_str());
          std::fflush(stdout);
        },
        [&](std::size_t j) {
          const std::size_t k = (*phase)[j];
          status[k] = jobs[j].status;
          const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          std::printf("  [%zu/%zu] %s: %s (%.0f s)\n", ++done, n, dirs[k].c_str(),
                      status[k] == 0 ? "done" : "FAILED, see run.log", el);
          std::fflush(stdout);
        });
  }

  // The table: the swept keys as given, the inputs that define each point and the headline
  // figures (runs/headline_figures.hpp), read from each point's summary.json.
  const auto& figures = runs::headline_figures();
  std::vector<runs::HeadlineFigure> inputs;
  for (const auto& f : runs::point_inputs()) {
    bool swept = false;
    for (const SweepAxis& a : grid.axes) swept = swept || a.column == f.column;
    if (!swept) inputs.push_back(f);
  }
  nlohmann::json axes = nlohmann::json::array(), table = nlohmann::json::array();
  for (std::size_t i = 0; i < grid.axes.size(); ++i) {
    nlohmann::json values = nlohmann::json::array();
    for (const SweepPoint& p : grid.points) values.push_back(value_json(p.values[i]));
    axes.push_back({{"key", grid.axes[i].key}, {"column", grid.axes[i].column}, {"values", values}});
  }
  std::ostringstream csv;
  std::string sep;
  for (const SweepAxis& a : grid.axes) csv << std::exchange(sep, ",") << csv_cell(a.column);
  for (const auto& f : inputs) csv << ',' << f.column;
  for (const auto& f : figures) csv << ',' << f.column;
  csv << ",dem_flow";
  if (replicas > 1) {
    for (const auto& f : figures) csv << ',' << f.column << "_std";
    csv << ",replicas";
  }
  csv << '\n';
  int failed = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const SweepPoint& p = grid.points[k];
    nlohmann::json row = {{"dir", dirs[k]}, {"status", status[k]}};
    sep.clear();
    for (std::size_t i = 0; i < grid.axes.size(); ++i) {
      row[grid.axes[i].column] = value_json(p.values[i]);
      csv << std::exchange(sep, ",") << csv_cell(p.values[i]);
    }
    if (status[k] != 0) {
      ++failed;
      csv << std::string(inputs.size() + figures.size(), ',') << ",failed";
      if (replicas > 1) csv << std::string(figures.size() + 1, ',');
      csv << '\n';
      table.push_back(row);
      continue;
    }
    const nlohmann::json s = io::read_json_file(dirs[k] + "/summary.json");
    for (const std::vector<runs::HeadlineFigure>* list : {&std::as_const(inputs), &figures})
      for (const auto& f : *list) {
        double v = 0.0;
        csv << ',';
        if (!runs::headline_value(s, f, v)) continue;  // an empty cell: the point has no such value
        row[f.column] = v;
        csv << shortest_text(v);
      }
    const bool steady = s.contains("dem") && s["dem"].value("steady", false);
    row["dem_flow"] = s.contains("dem") ? s["dem"].value("steady_state", "") : "";
    row["dem_flow_steady"] = steady;
    row["warnings"] = s.value("warnings", nlohmann::json::array());
    csv << ',' << (steady ? "steady" : s.contains("dem") ? "NOT steady" : "no DEM");
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
  io::write_json_file(out_dir + "/sweep.json", {{"case", case_path}, {"axes", axes}, {"points", table}});
  std::printf("centrec sweep %s: %zu points, %d failed; wrote %s/sweep.csv and sweep.json\n", case_path.c_str(), n,
              failed, out_dir.c_str());
  std::fputs(csv.str().c_str(), stdout);
  run_plot_script("centrec sweep", "plot_sweep.py", {out_dir}, charts);
  return failed ? 1 : 0;
}

}  // namespace centrec::cli
