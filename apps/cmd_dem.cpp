// `centrec dem CASE.yaml --out DIR`: a DEM-only run of the CentRec scene.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "atomic_write.hpp"
#include "dem_output_h5.hpp"
#include "case_file.hpp"
#include "commands.hpp"
#include "dem/film/steady_state.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_sampler.hpp"
#include "progress_meter.hpp"
#include "summary_json.hpp"

namespace centrec::cli {

namespace {

struct DemOptions {
  std::string case_path, out_dir = "out/dem";
  int threads = -1;         // -1 = from the case
  double duration = -1.0;   // -1 = from the case
};

void print_dem_help() {
  std::printf(
      "usage: centrec dem CASE.yaml [--out DIR] [--threads N] [--duration SECONDS]\n\n"
      "Runs the DEM of the CentRec drum (or periodic slice) described by the case's\n"
      "`dem:` section and writes DIR/summary.json (headline figures and the resolved\n"
      "configuration), DIR/dem.h5 (mass flows, averaged film fields, particle snapshots;\n"
      "units as attributes), DIR/dem.xmf (open in ParaView) and DIR/mass_flow.csv.\n"
      "--threads and --duration override run.threads and run.duration.\n");
}

DemOptions parse(const Args& args) {
  DemOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(name) + " needs a value");
      return args[++i];
    };
    if (a == "--out") o.out_dir = value("--out");
    else if (a == "--threads") o.threads = std::stoi(value("--threads"));
    else if (a == "--duration") o.duration = std::stod(value("--duration"));
    else if (!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
    else if (o.case_path.empty()) o.case_path = a;
    else throw std::invalid_argument("more than one case file given");
  }
  if (o.case_path.empty()) throw std::invalid_argument("no case file given (centrec dem --help)");
  return o;
}

// Mass flow over the last `window` seconds of the log, kg/s: {fed, out}.
std::pair<double, double> recent_flows(const std::vector<dem::scene::MassFlowSample>& log, double window) {
  if (log.size() < 2) return {0.0, 0.0};
  const auto& last = log.back();
  std::size_t k = log.size() - 1;
  while (k > 0 && last.time - log[k].time < window) --k;
  const double dt = last.time - log[k].time;
  if (dt <= 0.0) return {0.0, 0.0};
  return {(last.fed - log[k].fed) / dt, (last.out - log[k].out) / dt};
}

}  // namespace

int cmd_dem(const Args& args) {
  if (wants_help(args)) {
    print_dem_help();
    return 0;
  }
  const DemOptions opt = parse(args);
  const CaseFile cf = read_case_file(opt.case_path);
  if (!cf.dem) throw std::invalid_argument(opt.case_path + " has no `dem:` section");
  DemCase dc = *cf.dem;
  if (opt.threads >= 0) dc.scene.threads = opt.threads;
  if (opt.duration > 0.0) dc.run.duration = opt.duration;
  ensure_directory(opt.out_dir);

  dem::scene::CentrecScene scene(dc.scene);
  auto& sim = scene.simulation();
  std::fprintf(stderr, "centrec dem: %s\n  %s\n  dt = %.3g s, %lld glued + %lld free particles, %d thread(s)\n",
               cf.path.c_str(), sim.time_step_advice().report().c_str(), sim.dt(),
               static_cast<long long>(scene.glued_particles()), static_cast<long long>(scene.free_particles()),
               sim.threads());

  const double period = scene.turn_period();
  const double total = dc.run.duration + dc.sampling.turns * period;
  ProgressMeter progress(total, dc.run.progress_interval);
  const double chunk = std::max(sim.dt() * scene.steps_per_batch(), std::min(0.01, dc.run.duration));
  double particle_steps = 0.0;
  auto advance = [&](auto&& body) {
    const std::int64_t s0 = sim.step_count();
    const double n0 = static_cast<double>(sim.size());
    body();
    particle_steps += 0.5 * (n0 + static_cast<double>(sim.size())) * static_cast<double>(sim.step_count() - s0);
    progress.update(sim.time(), sim.time() / period, particle_steps);
  };
  // Spin-up (filling, reaching steady state), then sampling turn by turn.
  while (sim.time() < dc.run.duration - 0.5 * sim.dt())
    advance([&] { scene.advance(std::min(chunk, dc.run.duration - sim.time())); });
  dem::scene::SceneSampler sampler(scene, dc.sampling.sampler);
  std::vector<NamedSnapshot> snapshots;
  auto keep_snapshot = [&] {
    char name[32];
    std::snprintf(name, sizeof name, "t%.6f", sim.time());
    snapshots.push_back({name, dem::scene::take_snapshot(sim)});
  };
  keep_snapshot();  // the film as sampling starts
  for (int t = 0; t < static_cast<int>(std::floor(dc.sampling.turns + 1e-9)); ++t)
    advance([&] { sampler.sample_turns(scene, 1.0); });
  if (sim.time() > snapshots.back().data.time) keep_snapshot();
  progress.update(sim.time(), sim.time() / period, particle_steps, true);
  progress.finish();
  const double wall = progress.elapsed();

  const auto& log = scene.mass_flow_log();
  const double window = dc.run.flow_window_turns * period;
  const auto [fed_rate, out_rate] = recent_flows(log, window);
  const auto stats = sim.neighbour_stats();
  const dem::scene::FilmFields fields = sampler.fields();

  nlohmann::json j;
  j["code_version"] = CENTREC_VERSION;
  j["case"] = cf.path;
  j["title"] = cf.title;
  j["mode"] = dc.scene.slice.enabled ? "slice" : "drum";
  j["simulated_time_s"] = sim.time();
  j["turns"] = sim.time() / period;
  j["dt_s"] = sim.dt();
  j["steps"] = sim.step_count();
  j["threads"] = sim.threads();
  j["free_particles"] = scene.free_particles();
  j["glued_particles"] = scene.glued_particles();
  j["holdup_kg"] = scene.holdup_mass();
  const bool fed = dc.scene.feeder.enabled && !dc.scene.slice.enabled;
  j["target_mdot_kg_s"] = fed ? dc.scene.feeder.mass_flow : 0.0;
  j["inlet_mdot_kg_s"] = fed_rate;
  j["outlet_mdot_kg_s"] = out_rate;
  j["flow_window_s"] = window;
  if (fed && log.size() > 2) {
    std::vector<double> t, in, out;
    for (std::size_t k = 1; k < log.size(); ++k) {
      const double h = log[k].time - log[k - 1].time;
      if (!(h > 0.0)) continue;
      t.push_back(log[k].time);
      in.push_back((log[k].fed - log[k - 1].fed) / h);
      out.push_back((log[k].out - log[k - 1].out) / h);
    }
    film::SteadyStateCriterion crit;
    crit.window = window;
    crit.tolerance = dc.run.steady_tolerance;
    const auto ss = film::find_steady_state(t.data(), in.data(), out.data(), t.size(), crit);
    j["steady_state"] = ss.steady;
    j["time_to_steady_state_s"] = ss.steady ? nlohmann::json(ss.time) : nlohmann::json(nullptr);
  }
  j["lost_kg"] = log.empty() ? 0.0 : log.back().lost;
  j["feeder_deferred_insertions"] = scene.feeder_stats().deferred;
  j["contacts_per_particle"] = stats.contacts_per_particle();
  j["particle_steps_per_s"] = wall > 0.0 ? particle_steps / wall : 0.0;
  j["wall_time_s"] = wall;
  j["sampled_turns"] = fields.turns;
  if (fields.snapshots > 0) {
    j["mean_film_thickness_d"] = fields.mean_thickness.mean_d;
    j["mean_film_thickness_std_d"] = fields.mean_thickness.std_d;
    nlohmann::json arcs = nlohmann::json::array();
    for (const auto& a : fields.zones.moving)
      arcs.push_back({{"start_deg", a.start * 180.0 / M_PI}, {"end_deg", a.end * 180.0 / M_PI}});
    j["moving_zones"] = arcs;
    j["theta_convention"] =
        "theta increases against the drum rotation; 90 deg = top (opposite gravity's transverse part)";
  }
  j["resolved_config"] = cf.resolved_yaml;
  io::write_json_file(opt.out_dir + "/summary.json", j);

  write_dem_h5(opt.out_dir, cf.path, cf.resolved_yaml, scene, fields, snapshots);

  std::ostringstream csv;
  csv << "# time_s,fed_kg,out_kg,lost_kg,holdup_kg,particles\n";
  for (const auto& s : log)
    csv << s.time << ',' << s.fed << ',' << s.out << ',' << s.lost << ',' << s.holdup << ',' << s.particles << '\n';
  write_text_atomically(opt.out_dir + "/mass_flow.csv", csv.str());

  std::printf("holdup %.4f kg (%lld particles), inlet %.3f g/s, outlet %.3f g/s over the last %.2f s\n",
              scene.holdup_mass(), static_cast<long long>(scene.free_particles()), fed_rate * 1e3, out_rate * 1e3,
              window);
  std::printf("%.3g particle-steps/s, wall time %.1f s; wrote %s/summary.json\n",
              wall > 0.0 ? particle_steps / wall : 0.0, wall, opt.out_dir.c_str());
  if (fields.snapshots > 0)
    std::printf("film thickness %.2f +- %.2f d over %zu turns\n", fields.mean_thickness.mean_d,
                fields.mean_thickness.std_d, fields.turns);
  return 0;
}

}  // namespace centrec::cli
