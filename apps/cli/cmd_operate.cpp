// centrec operate: the speed and mass flow that reach a target outlet temperature, from an
// operating map's film surrogate (docs/operating.md).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "cli/case_overrides.hpp"
#include "cli/child_processes.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/plot_scripts.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/run_folder.hpp"
#include "io/summary_json.hpp"
#include "runs/operating_point.hpp"
#include "thermal/table_csv.hpp"

namespace centrec::cli {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json answer_json(const runs::SurrogateThermal::Answer& a) {
  return {{"T_out_K", a.T_out},
          {"efficiency", a.efficiency},
          {"T_surface_max_K", a.T_surface_max},
          {"T_max_K", a.T_max},
          {"film_thickness_d", a.thickness_d},
          {"velocity_factor", a.velocity_factor}};
}

}  // namespace

int cmd_operate(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec operate CASE.yaml --map SWEEP_DIR --target-outlet K --out DIR [--speeds N]\n"
        "                       [--min-thickness-d X] [--min-margin-rpm R] [--check [--check-runs N]]\n"
        "                       [--transient FLUX.csv [--film-response-s S]\n"
        "                       [--turndown F]] [--set KEY=VALUE ...] [figure flags]\n\n"
        "The speed and mass flow at which the receiver of CASE reaches the target outlet\n"
        "temperature (kelvin) at the case's flux (docs/operating.md). SWEEP_DIR is a `centrec\n"
        "sweep` of CASE over speed x mass flow (its operating map; or of another receiver of the\n"
        "same scaled film: the same dem: section, dem_diameter_d, tilt and L/D, whose map is read\n"
        "as this one's by eqs 1-2): a point is usable when its\n"
        "DEM film was steady and carried the DEM's flow within 3 %%; a grid cell with four usable\n"
        "corners is inside the stable window. The usable points' films are fitted as smooth\n"
        "functions of speed and mass flow (the film surrogate; its leave-one-out error is\n"
        "printed, thickness, velocity, solid fraction, dispersion and the T_out it gives), the\n"
        "case's thermal model runs on the surrogate's film, and at N speeds across the window\n"
        "(default 7) the mass flow that gives the target is found; the point of highest\n"
        "efficiency (with a film at least X d thick and at least R rpm from the window's speed\n"
        "edges: efficiency rises towards the film's lock) is the answer, with its margin to the\n"
        "window's edges. --check runs the full coupled run there (`centrec run --speed-rpm\n"
        "--mass-flow`, its DEM included: minutes) into DIR/check and compares its T_out; with\n"
        "--check-runs N (default 1), while it misses the target by more than 3 K, secant steps\n"
        "in the mass flow at the same speed (the first through the surrogate's slope, then\n"
        "through the last two full runs) make up to N full runs (DIR/check_2, ...): the last\n"
        "within 3 K is the checked operating point.\n"
        "--transient runs a flux history (CSV time_s,flux_scale; cases/cloud_70pct_60s.csv is a\n"
        "passing cloud) at the answer three ways: the mass flow held, a PI controller on T_out\n"
        "(tuned on the film's step response), and the PI with the flux fed forward; the mass flow\n"
        "follows its command with the film's response time and stays above the turndown\n"
        "(default 0.2); writes DIR/operate_transient.csv.\n"
        "Writes DIR/operate.json, DIR/operate_map.csv (T_out and efficiency over the map) and\n"
        "the figures of apps/plot_operate.py (operate_map.png, operate_transient.png).\n");
    return 0;
  }
  std::string case_path, map_dir, out_dir;
  double target = 0.0;
  runs::OperatingCriterion criterion;
  int n_speeds = 7, check_runs = 1;
  bool check = false, overwrite = false;
  CommandLine app("operate");
  app.add_option("CASE", case_path)->required();
  app.add_option("--map", map_dir, "a `centrec sweep` of CASE over speed x mass flow")->required();
  app.add_option("--target-outlet", target, "the outlet temperature to reach, K")
      ->required()
      ->check(CLI::Range(300.0, 2000.0));
  app.add_option("--out", out_dir)->required();
  app.add_option("--speeds", n_speeds, "speeds tried across the window")->check(CLI::Range(1, 50));
  app.add_option("--min-thickness-d", criterion.min_thickness_d, "the thinnest film accepted, in particle diameters")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--min-margin-rpm", criterion.min_margin_rpm,
                 "the least distance of the answer's speed from the window's speed edges, rpm")
      ->check(CLI::Range(0.0, 1e4));
  app.add_flag("--check", check, "run the full coupled run at the answer and compare");
  app.add_option("--check-runs", check_runs, "full runs the check may make, secant steps in the mass flow between")
      ->check(CLI::Range(1, 10));
  std::string transient_csv;
  double film_response = std::numeric_limits<double>::quiet_NaN(), turndown = 0.2;
  app.add_option("--transient", transient_csv, "a flux history (CSV time_s,flux_scale) to run at the answer")
      ->option_text("FLUX.csv");
  app.add_option("--film-response-s", film_response,
                 "the film's response time to a feed change, s (default: " +
                     config::shortest_text(runs::kFilmResponseOverResidence) +
                     " of its residence time, as measured on a fed drum's feed step, docs/operating.md)")
      ->check(CLI::Range(0.0, 1e4));
  app.add_option("--turndown", turndown, "the lowest mass flow the feeder gives, as a fraction of the answer's")
      ->check(CLI::Range(0.01, 1.0));
  add_overwrite_flag(app, overwrite);
  config::Overrides overrides;
  add_override_flags(app, overrides, "operate");
  FigureOptions figures;
  add_figure_flags(app, figures);
  app.read(args);
  // dem.run.threads changes no result (the DEM cache's key leaves it out): it sets how many
  // cores the check's full runs take, e.g. one beside a long DEM.
  for (const auto& [key, value] : overrides.keys)
    if (key.rfind("thermal.", 0) != 0 && key != "dem.run.threads")
      throw UsageError("--set " + key + "=" + value +
                       ": the map's films were run with the case's DEM and receiver; operate changes only "
                       "thermal.* keys (the flux, the inlet temperature, the cavity) and dem.run.threads");
  const config::CaseFile cf = checked_overrides(config::read_case_file(case_path), overrides, "operate");
  if (!cf.receiver || !cf.thermal || !cf.thermal->film_source.from_dem())
    throw UsageError(case_path +
                     ": operate needs a receiver whose film comes from its DEM (a `receiver:`, `dem:` and "
                     "`thermal:` section, no `film:`), as its operating map was run");
  const double receiver_d = cf.receiver->op.diameter;
  // The map must be of this receiver, or of one of the same scaled film (eqs 1-2), read as this one's.
  const runs::MapScaling scaling = runs::map_scaling_for(map_dir, cf.resolved_yaml);
  const runs::OperatingMap map = runs::read_operating_map(map_dir, scaling);
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec operate " + case_path, folder_use(overwrite));
  const auto t0 = std::chrono::steady_clock::now();

  // 1. The map and its window.
  nlohmann::json j;
  j["case"] = case_path;
  j["map"] = map_dir;
  int usable = 0;
  std::printf("centrec operate %s: map %s, %zu points (%zu speeds x %zu mass flows)\n", case_path.c_str(),
              map_dir.c_str(), map.points.size(), map.speeds.size(), map.flows.size());
  if (!scaling.identity()) {
    std::printf("  the map is of another receiver of the same scaled film (the same DEM by eqs 1-3), read as this "
                "one's: speeds x %.6g (omega^2 R kept), mass flows x %.6g (mdot / R kept), film length x %.6g\n",
                scaling.speed, scaling.flow, scaling.length);
    j["map_scaling"] = {{"speed", scaling.speed}, {"mass_flow", scaling.flow}, {"length", scaling.length}};
  }
  for (const auto& p : map.points) {
    usable += p.usable;
    std::printf("  %8.3f rpm  %8.4f kg/s  %s  %s\n", p.speed_rpm, p.mass_flow, p.usable ? "usable  " : "NOT used",
                p.state.c_str());
    j["map_points"].push_back({{"speed_rpm", p.speed_rpm},
                               {"mass_flow_kg_s", p.mass_flow},
                               {"usable", p.usable},
                               {"state", p.state},
                               {"dir", p.dir}});
  }

  // 2. The film surrogate and its leave-one-out error, in the films and in T_out.
  const coupling::FilmSurrogate surrogate(runs::surrogate_samples(map, receiver_d));
  const runs::SurrogateThermal thermal(*cf.thermal, surrogate, receiver_d);
  std::printf("film surrogate of %d usable points (fits in ln speed, ln mass flow; leave-one-out error):\n", usable);
  if (surrogate.samples().size() >= 4) {
    for (const auto& e : surrogate.leave_one_out()) {
      std::printf("  %-28s %-7s rms %.3g, max %.3g %s (range over the map %.3g)\n", e.quantity.c_str(),
                  coupling::basis_name(e.basis), e.rms, e.max_abs, e.unit.c_str(), e.range);
      j["surrogate"]["leave_one_out"].push_back({{"quantity", e.quantity},
                                                 {"unit", e.unit},
                                                 {"basis", coupling::basis_name(e.basis)},
                                                 {"rms", e.rms},
                                                 {"max_abs", e.max_abs},
                                                 {"range", e.range}});
    }
    double sum = 0.0, worst = 0.0, solve_s = 0.0;
    const auto& s = surrogate.samples();
    for (std::size_t i = 0; i < s.size(); ++i) {
      const coupling::FilmSurrogate rest = surrogate.without(i);
      const runs::SurrogateThermal rest_thermal(*cf.thermal, rest, receiver_d);
      const auto own = thermal.on_film(s[i].film, s[i].mass_flow);
      const auto left_out = rest_thermal.at(s[i].speed_rpm, s[i].mass_flow);
      const double e = left_out.T_out - own.T_out;
      sum += e * e;
      worst = std::max(worst, std::abs(e));
      solve_s += left_out.seconds;
      j["surrogate"]["T_out_leave_one_out"].push_back({{"speed_rpm", s[i].speed_rpm},
                                                       {"mass_flow_kg_s", s[i].mass_flow},
                                                       {"own_film_T_out_K", own.T_out},
                                                       {"surrogate_T_out_K", left_out.T_out}});
    }
    const double rms = std::sqrt(sum / static_cast<double>(s.size()));
    std::printf("  %-28s         rms %.3g, max %.3g K (the case's thermal model on the left-out film against "
                "the point's own; %.2f s per solve)\n",
                "T_out", rms, worst, solve_s / static_cast<double>(s.size()));
    j["surrogate"]["T_out_rms_K"] = rms;
    j["surrogate"]["T_out_max_K"] = worst;
  } else {
    std::printf("  (fewer than 4 usable points: no leave-one-out check)\n");
  }

  // 3. The operating point.
  const runs::OperatingAnswer a = runs::find_operating_point(map, thermal, target, n_speeds, criterion);
  std::printf("target T_out %.2f K (%.2f C): %s\n", target, target - 273.15, a.criterion.c_str());
  j["candidates"] = nlohmann::json::array();
  if (!a.candidates.empty())
    std::printf("  %9s %11s %9s %10s %9s %7s\n", "speed rpm", "mdot kg/s", "T_out K", "efficiency", "film d",
                "solves");
  for (std::size_t k = 0; k < a.candidates.size(); ++k) {
    const auto& c = a.candidates[k];
    nlohmann::json row = {{"speed_rpm", c.speed_rpm}, {"found", c.found}, {"solves", c.solves}};
    if (c.found) {
      std::printf("  %9.3f %11.5f %9.2f %10.4f %9.2f %7d%s\n", c.speed_rpm, c.mass_flow, c.answer.T_out,
                  c.answer.efficiency, c.answer.thickness_d, c.solves, static_cast<int>(k) == a.best ? "  <- best" : "");
      row["mass_flow_kg_s"] = c.mass_flow;
      row.update(answer_json(c.answer));
    } else {
      std::printf("  %9.3f  none: %s\n", c.speed_rpm, c.why_not.c_str());
      row["why_not"] = c.why_not;
    }
    j["candidates"].push_back(row);
  }
  j["target_T_out_K"] = target;
  j["criterion"] = a.criterion;
  int status = 0;
  if (a.best < 0) {
    const std::string why = a.why_none.empty() ? "no speed of the window reaches the target: see the spans above"
                                               : a.why_none + ": run the unusable points again (their reasons above)";
    std::printf("no operating point for %.2f K: %s\n", target, why.c_str());
    j["operating_point"] = nullptr;
    j["why_no_operating_point"] = why;
    status = 3;
  } else {
    const auto& b = a.candidates[a.best];
    std::printf(
        "operating point: %.3f rpm, %.5f kg/s -> T_out %.2f K, efficiency %.4f, film %.2f d, peak surface %.1f K, "
        "hottest particles %.1f K\n"
        "  margin to the window: speed -%.3f / +%.3f rpm, mass flow -%.5f / +%.5f kg/s\n",
        b.speed_rpm, b.mass_flow, b.answer.T_out, b.answer.efficiency, b.answer.thickness_d, b.answer.T_surface_max, b.answer.T_max,
        b.margin.speed_below, b.margin.speed_above, b.margin.flow_below, b.margin.flow_above);
    j["operating_point"] = {{"speed_rpm", b.speed_rpm}, {"mass_flow_kg_s", b.mass_flow}};
    j["operating_point"].update(answer_json(b.answer));
    j["operating_point"]["margin"] = {{"speed_below_rpm", b.margin.speed_below},
                                      {"speed_above_rpm", b.margin.speed_above},
                                      {"mass_flow_below_kg_s", b.margin.flow_below},
                                      {"mass_flow_above_kg_s", b.margin.flow_above}};
  }

  // 4. T_out and efficiency over the map's box, for the figure.
  {
    // Off the window the surrogate extrapolates: where its film is no film (no flow left to
    // carry the mass flow) the grid holds nan and says why once, not the whole command fails.
    constexpr int kGrid = 9;
    std::ostringstream csv;
    csv << "speed_rpm,mass_flow_kg_s,inside_window,T_out_K,efficiency\n";
    int failed = 0;
    std::string why;
    for (int i = 0; i < kGrid; ++i)
      for (int k = 0; k < kGrid; ++k) {
        const double v = map.speeds.front() + (map.speeds.back() - map.speeds.front()) * i / (kGrid - 1);
        const double m = map.flows.front() * std::pow(map.flows.back() / map.flows.front(), k / (kGrid - 1.0));
        const bool inside = map.inside(v, m);
        csv << shortest_text(v) << ',' << shortest_text(m) << ',' << (inside ? 1 : 0) << ',';
        try {
          const auto r = thermal.at(v, m);
          csv << shortest_text(r.T_out) << ',' << shortest_text(r.efficiency) << '\n';
        } catch (const std::exception& e) {
          if (inside) throw;  // inside the window the surrogate must hold
          csv << "nan,nan\n";
          if (failed++ == 0) why = e.what();
        }
      }
    io::write_text_atomically(out_dir + "/operate_map.csv", csv.str());
    if (failed > 0) {
      std::printf("map figure: %d of %d grid points off the window have no surrogate film (%s): nan there\n", failed,
                  kGrid * kGrid, why.c_str());
      j["map_grid_points_without_film"] = failed;
    }
  }

  // 5. The full coupled run at the answer, and secant steps in the mass flow while it misses.
  if (check && a.best >= 0) {
    const auto& b = a.candidates[a.best];
    // The surrogate's dT_out/dmdot at the answer: central, or one-sided inward where the
    // extrapolated surrogate has no film on one side (the answer on the map's flow edge).
    const double dm = 0.01 * b.mass_flow;
    auto T_at = [&](double m) {
      try {
        return thermal.at(b.speed_rpm, m).T_out;
      } catch (const std::exception&) {
        return std::numeric_limits<double>::quiet_NaN();
      }
    };
    const double T_hi = T_at(b.mass_flow + dm), T_lo = T_at(b.mass_flow - dm);
    const double slope = !std::isnan(T_hi) && !std::isnan(T_lo) ? (T_hi - T_lo) / (2.0 * dm)
                         : !std::isnan(T_hi)                    ? (T_hi - b.answer.T_out) / dm
                                                                : (b.answer.T_out - T_lo) / dm;
    int failed = 0;
    std::vector<nlohmann::json> runs_made;
    auto full_T_out = [&](double mdot) {
      const std::string dir = out_dir + (runs_made.empty() ? "/check" : "/check_" + std::to_string(runs_made.size() + 1));
      ChildJob job;
      job.argv = {own_executable(), "run", case_path, "--speed-rpm", shortest_text(b.speed_rpm), "--mass-flow",
                  shortest_text(mdot), "--out", dir, "--no-plots"};
      if (overwrite) job.argv.push_back("--overwrite");
      for (const std::string& s : override_args(overrides, "run")) job.argv.push_back(s);
      job.log = dir + ".log";
      std::printf("checking with the full coupled run (DEM included) at %.5g kg/s: %s, log %s\n", mdot, dir.c_str(),
                  job.log.c_str());
      std::fflush(stdout);
      std::vector<ChildJob> jobs{job};
      run_child_jobs(jobs, 1, {}, {});
      if (jobs[0].status != 0) {
        failed = jobs[0].status;
        runs_made.push_back({{"dir", dir}, {"mass_flow_kg_s", mdot}, {"status", failed}, {"log", job.log}});
        throw std::runtime_error("the check run at " + shortest_text(mdot) + " kg/s FAILED (status " +
                                 std::to_string(failed) + "), see " + job.log);
      }
      const nlohmann::json s = io::read_json_file(dir + "/summary.json");
      const double T = s.at("T_out_K").get<double>();
      std::printf("  full run: T_out %.2f K (%+.2f K from the target: %s), efficiency %.4f, DEM %s\n", T, T - target,
                  std::abs(T - target) <= 3.0 ? "within 3 K" : "NOT within 3 K", s.at("efficiency").get<double>(),
                  s["dem"].value("steady_state", "").c_str());
      runs_made.push_back({{"dir", dir},
                           {"mass_flow_kg_s", mdot},
                           {"T_out_K", T},
                           {"off_target_K", T - target},
                           {"within_3K", std::abs(T - target) <= 3.0},
                           {"efficiency", s.at("efficiency")},
                           {"dem_steady", s["dem"].value("steady", false)}});
      return T;
    };
    try {
      const runs::CheckRefinement r =
          runs::refine_by_full_runs(target, b.mass_flow, slope, map.flow_span(b.speed_rpm), check_runs, 3.0, full_T_out);
      j["check"] = runs_made.back();
      j["check"]["surrogate_slope_K_per_kg_s"] = slope;
      j["check"]["runs"] = runs_made;
      if (r.why_stopped.empty()) {
        const auto& last = runs_made.back();
        std::printf("checked operating point: %.3f rpm, %.5f kg/s -> T_out %.2f K (full run), efficiency %.4f\n",
                    b.speed_rpm, last["mass_flow_kg_s"].get<double>(), last["T_out_K"].get<double>(),
                    last["efficiency"].get<double>());
        j["checked_operating_point"] = {{"speed_rpm", b.speed_rpm},
                                        {"mass_flow_kg_s", last["mass_flow_kg_s"]},
                                        {"T_out_K", last["T_out_K"]},
                                        {"efficiency", last["efficiency"]},
                                        {"full_runs", runs_made.size()}};
      } else {
        std::printf("  no full run within 3 K: %s\n", r.why_stopped.c_str());
        j["check"]["why_not_within_3K"] = r.why_stopped;
        status = 5;
      }
    } catch (const std::runtime_error& e) {
      if (failed == 0) throw;
      std::printf("  %s\n", e.what());
      j["check"] = runs_made.back();
      j["check"]["runs"] = runs_made;
      status = 4;
    }
  }
  // 6. A flux history at the answer.
  if (!transient_csv.empty() && a.best >= 0) {
    const auto& b = a.candidates[a.best];
    const thermal::TimeFactor flux = thermal::read_flux_time_csv(transient_csv);
    thermal::ControlledTransientSettings st;
    st.t_end = flux.table_t.back();
    st.tau_film = film_response;
    st.m_min = turndown;
    const auto t1 = std::chrono::steady_clock::now();
    // The film follows the surrogate over the map's mass flows (beyond them, the nearest's film).
    const runs::CloudResponse cr =
        runs::cloud_response(thermal, b.speed_rpm, b.mass_flow, flux, st, {map.flows.front(), map.flows.back()});
    const double tau = cr.film_response;
    std::printf("flux history %s at the operating point (%.0f s; film residence time %.2f s, response time %.2f s%s, "
                "turndown %.2f):\n  PI tuned on the film's step response: gain %.1f K per unit flow, dead time %.2f s, "
                "time constant %.2f s -> kp %.4g 1/K, ki %.4g 1/(K s)\n",
                transient_csv.c_str(), st.t_end, cr.residence_time, tau,
                std::isnan(film_response) ? (" (" + config::shortest_text(runs::kFilmResponseOverResidence) +
                                                 " of it, as a fed drum's feed step measured it)")
                                                    .c_str()
                                              : " (--film-response-s)",
                turndown,
                cr.tuning.gain, cr.tuning.fit.dead_time, cr.tuning.fit.time_constant, cr.tuning.gains.kp,
                cr.tuning.gains.ki);
    const std::pair<const char*, const thermal::ControlledTransientResult*> modes[3] = {
        {"mass flow held", &cr.fixed}, {"PI on T_out", &cr.pi}, {"PI + flux feedforward", &cr.feedforward}};
    std::ostringstream csv;
    csv << "t_s,flux_factor";
    for (const char* m : {"fixed", "pi", "feedforward"})
      csv << ',' << m << "_mass_flow_kg_s," << m << "_T_out_K," << m << "_T_surface_max_K," << m << "_T_max_K";
    csv << '\n';
    for (std::size_t k = 0; k < cr.fixed.samples.size(); ++k) {
      csv << shortest_text(cr.fixed.samples[k].t) << ',' << shortest_text(cr.fixed.samples[k].flux_factor);
      for (const auto& [name, r] : modes) {
        const auto& c = r->samples[k];
        csv << ',' << shortest_text(c.mass_flow) << ',' << shortest_text(c.T_out) << ','
            << shortest_text(c.T_surface_max) << ',' << shortest_text(c.T_max);
      }
      csv << '\n';
    }
    io::write_text_atomically(out_dir + "/operate_transient.csv", csv.str());
    for (const auto& [name, r] : modes) {
      double peak = 0.0, outside = 0.0, surface = 0.0, hottest = 0.0, m_low = 1e300;
      for (std::size_t k = 0; k < r->samples.size(); ++k) {
        const auto& c = r->samples[k];
        peak = std::max(peak, std::abs(c.T_out - r->T_set));
        if (k > 0 && std::abs(c.T_out - r->T_set) > 15.0) outside += c.t - r->samples[k - 1].t;
        surface = std::max(surface, c.T_surface_max);
        hottest = std::max(hottest, c.T_max);
        m_low = std::min(m_low, c.mass_flow);
      }
      std::printf("  %-22s peak |T_out - %.2f K| %7.2f K, %5.0f s outside +-15 K, lowest flow %.4g kg/s, peak "
                  "surface %.1f K, hottest particles %.1f K\n",
                  name, r->T_set, peak, outside, m_low, surface, hottest);
      j["transient"][name] = {{"peak_deviation_K", peak},
                              {"seconds_outside_15K", outside},
                              {"lowest_mass_flow_kg_s", m_low},
                              {"peak_surface_K", surface},
                              {"peak_particle_K", hottest},
                              {"films_taken", r->refilms},
                              {"film_change_enthalpy_J", r->refilm_enthalpy},
                              {"film_change_enthalpy_abs_J", r->refilm_enthalpy_abs}};
    }
    if (cr.film_follows) {
      std::printf("  the film followed the surrogate (%.4g-%.4g kg/s; beyond, the nearest mapped flow's film): films "
                  "taken held / PI / PI+FF %d / %d / %d; enthalpy their changes created %+.3g / %+.3g / %+.3g kJ "
                  "(magnitudes %.3g / %.3g / %.3g kJ; the film holds %.3g kJ above the inlet)\n",
                  map.flows.front(), map.flows.back(), cr.fixed.refilms, cr.pi.refilms, cr.feedforward.refilms,
                  cr.fixed.refilm_enthalpy / 1e3, cr.pi.refilm_enthalpy / 1e3, cr.feedforward.refilm_enthalpy / 1e3,
                  cr.fixed.refilm_enthalpy_abs / 1e3, cr.pi.refilm_enthalpy_abs / 1e3,
                  cr.feedforward.refilm_enthalpy_abs / 1e3, cr.film_enthalpy / 1e3);
      j["transient"]["film_follows_surrogate"] = true;
      j["transient"]["film_enthalpy_J"] = cr.film_enthalpy;
    }
    j["transient"]["flux_file"] = transient_csv;
    j["transient"]["residence_time_s"] = cr.residence_time;
    j["transient"]["film_response_s"] = tau;
    j["transient"]["film_response_source"] =
        std::isnan(film_response) ? "fed drum's feed step (" + config::shortest_text(runs::kFilmResponseOverResidence) +
                                        " x the residence time)"
                                  : std::string("--film-response-s");
    j["transient"]["turndown"] = turndown;
    j["transient"]["kp_per_K"] = cr.tuning.gains.kp;
    j["transient"]["ki_per_K_s"] = cr.tuning.gains.ki;
    j["transient"]["seconds"] = seconds_since(t1);
  }
  j["wall_time_s"] = seconds_since(t0);
  if (!flags_text(overrides, "operate").empty()) j["command_line_overrides"] = flags_text(overrides, "operate");
  io::write_json_file(out_dir + "/operate.json", j);
  run_plot_script("centrec operate", "plot_operate.py", {out_dir}, figures);
  std::printf("wrote %s/{operate.json,operate_map.csv} (%.1f s)\n", out_dir.c_str(), seconds_since(t0));
  return status;
}

}  // namespace centrec::cli
