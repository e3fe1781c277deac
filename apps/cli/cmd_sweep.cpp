// `centrec sweep CASE.yaml --out DIR`: the operating map. Runs `centrec
// run` over the case's sweep grid (speed x mass flow) as parallel processes, then tabulates
// outlet temperature, efficiency and k_eff (DIR/sweep.csv, DIR/sweep.json) and charts them
// (apps/plot_sweep.py).
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "cli/command_line.hpp"
#include "cli/plot_scripts.hpp"
#include "cli/commands.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/summary_json.hpp"
#include "config/case_receiver.hpp"
#include "coupling/scaling_laws.hpp"

namespace centrec::cli {

namespace {
struct Point {
  double rpm = 0.0, mdot = 0.0;
  std::string dir;
  int status = -1;
};

void print_sweep_help() {
  std::printf(
      "usage: centrec sweep CASE.yaml --out DIR [--parallel N] [--cache DIR]\n\n"
      "Runs the coupled `centrec run` for every point of the case's `sweep:` grid\n"
      "(speed_rpm x mass_flow: the receiver's operating point, or the DEM drum's without a\n"
      "receiver), N processes at a time (sweep.parallel, one DEM thread each), each into\n"
      "DIR/rpm<N>_mdot<M>/ with its log in run.log. Then writes DIR/sweep.csv and\n"
      "DIR/sweep.json (outlet temperature, efficiency, k_eff and its parts, film thickness per\n"
      "point) and the charts of apps/plot_sweep.py (DIR/sweep_*.png).\n");
}

// Starts `centrec run` for one point with stdout/stderr in DIR/run.log; returns the pid.
// Every point runs with --allow-unsteady: a point whose DEM did not reach steady flow is
// reported as such in the table rather than lost.
pid_t start_point(const std::string& exe, const std::string& case_path, const std::string& cache, const Point& p,
                  bool allow_small_drum) {
  io::ensure_directory(p.dir);
  // Full precision: std::to_string's six decimals would turn 1e-7 kg/s into 0.
  auto exact = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  std::vector<std::string> argv_s = {exe,   "run",     case_path, "--out",         p.dir,
                                     "--cache", cache, "--speed-rpm", exact(p.rpm), "--mass-flow",
                                     exact(p.mdot), "--threads", "1", "--no-plots", "--allow-unsteady"};
  if (allow_small_drum) argv_s.push_back("--allow-small-drum");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("centrec sweep: fork failed");
  if (pid == 0) {
    const int fd = open((p.dir + "/run.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    std::vector<char*> argv;
    for (const auto& s : argv_s) argv.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

std::string point_name(double rpm, double mdot) {
  char b[96];
  std::snprintf(b, sizeof b, "rpm%g_mdot%g", rpm, mdot);
  return b;
}
}  // namespace

int cmd_sweep(const Args& args) {
  if (wants_help(args)) {
    print_sweep_help();
    return 0;
  }
  std::string case_path, out_dir, cache;
  int parallel = 0;
  bool allow_small_drum = false;
  CommandLine app("sweep");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir)->required();
  app.add_option("--cache", cache);
  app.add_option("--parallel", parallel);
  app.add_flag("--allow-small-drum", allow_small_drum,
               "run a DEM drum below the scale-down validity threshold (the outputs carry a warning)");
  app.read(args);
  const config::CaseFile cf = config::read_case_file(case_path);
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
  io::ensure_directory(out_dir);
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) throw std::runtime_error("centrec sweep: cannot find its own executable");
  exe[n] = '\0';

  std::vector<Point> points;
  for (double rpm : cf.sweep->speed_rpm)
    for (double mdot : cf.sweep->mass_flow) points.push_back({rpm, mdot, out_dir + "/" + point_name(rpm, mdot)});
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t next = 0, done = 0;
  std::vector<std::pair<pid_t, std::size_t>> running;
  while (done < points.size()) {
    while (next < points.size() && static_cast<int>(running.size()) < parallel) {
      running.push_back({start_point(exe, case_path, cache, points[next], allow_small_drum), next});
      std::printf("  started %s\n", points[next].dir.c_str());
      std::fflush(stdout);
      ++next;
    }
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid < 0) throw std::runtime_error("centrec sweep: wait failed");
    for (std::size_t k = 0; k < running.size(); ++k) {
      if (running[k].first != pid) continue;
      Point& p = points[running[k].second];
      p.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
      ++done;
      const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("  [%zu/%zu] %s: %s (%.0f s)\n", done, points.size(), p.dir.c_str(),
                  p.status == 0 ? "done" : "FAILED, see run.log", el);
      std::fflush(stdout);
      running.erase(running.begin() + static_cast<long>(k));
      break;
    }
  }

  // Table of the headline figures.
  nlohmann::json table = nlohmann::json::array();
  std::ostringstream csv;
  csv << "speed_rpm,mass_flow_kg_s,T_out_K,efficiency,k_eff_W_mK,k_bed_W_mK,k_rad_W_mK,k_mix_W_mK,"
         "film_thickness_d,imposed_mdot_kg_s,dem_flow\n";
  int failed = 0;
  for (const Point& p : points) {
    nlohmann::json row = {{"speed_rpm", p.rpm}, {"mass_flow_kg_s", p.mdot}, {"dir", p.dir}, {"status", p.status}};
    csv << p.rpm << ',' << p.mdot << ',';
    std::ifstream in(p.dir + "/summary.json");
    if (p.status == 0 && in) {
      const nlohmann::json s = nlohmann::json::parse(in);
      const auto& k = s["k_eff"]["film_mean"];
      row["T_out_K"] = s["T_out_K"];
      row["efficiency"] = s["efficiency"];
      row["k_eff"] = k;
      row["film_thickness_d"] = s["film"]["mean_thickness_d"];
      row["imposed_mdot_kg_s"] = s["mass_flow_kg_s"];  // the point's own (receiver) flow
      const bool steady = s["dem"]["steady"].get<bool>();
      const std::string flow = steady ? "steady" : "NOT steady";
      row["dem_flow"] = s["dem"]["steady_state"];
      row["dem_flow_steady"] = steady;
      row["warnings"] = s["warnings"];
      csv << s["T_out_K"].get<double>() << ',' << s["efficiency"].get<double>() << ','
          << k["k_eff"].get<double>() << ',' << k["bed_conduction"].get<double>() << ','
          << k["radiation"].get<double>() << ',' << k["mixing"].get<double>() << ','
          << s["film"]["mean_thickness_d"].get<double>() << ','
          << s["mass_flow_kg_s"].get<double>() << ',' << flow << '\n';
    } else {
      ++failed;
      csv << ",,,,,,,,failed\n";
    }
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
