#include "runs/dem_run_report.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "coupling/scaling_laws.hpp"
#include "dem/film/steady_state.hpp"
#include "dem/scene/mass_flow_window.hpp"
#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
#include "io/dem_output_h5.hpp"
#include "io/summary_json.hpp"
#include "runs/provenance.hpp"

namespace centrec::runs {

namespace {

// Steady state of the fed drum from the per-interval inlet and outlet flows of the log.
film::SteadyStateResult steady_state(const std::vector<dem::scene::MassFlowSample>& log, double window,
                                     double tolerance) {
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
  crit.tolerance = tolerance;
  return film::find_steady_state(t.data(), in.data(), out.data(), t.size(), crit);
}

// What a user of this DEM run must know before taking its film (summary.json "warnings",
// and stderr): a flow that is not steady, a feeder that delivered less than asked, a spin-up
// that ran past run.duration.
std::vector<std::string> dem_run_warnings(const config::DemCase& dc, const io::DemRunResult& r) {
  std::vector<std::string> w;
  const double period = dem::scene::turn_period(dc.scene), window = dc.run.flow_window_turns * period;
  const auto steady = dem::scene::flow_steadiness(r.mass_flow, dc.scene, window, dc.run.steady_tolerance);
  char b[320];
  if (!steady.steady) {
    std::snprintf(b, sizeof b, "the flow is not steady over the last %.3g s (", window);
    w.push_back(b + steady.describe() + "): a coupled run refuses this film without --allow-unsteady");
  }
  const auto flows = dem::scene::window_flows(r.mass_flow, window);
  const double asked = dc.scene.feeder.mass_flow;
  if (dc.scene.feeder.enabled && !dc.scene.slice.enabled && r.feeder_deferred > 0 && flows.fed < 0.9 * asked) {
    std::snprintf(b, sizeof b,
                  "the feeder delivered %.4g g/s of the %.4g g/s asked (%lld insertions deferred: its region was "
                  "full); enlarge dem.feeder's region or lower the mass flow",
                  flows.fed * 1e3, asked * 1e3, static_cast<long long>(r.feeder_deferred));
    w.push_back(b);
  }
  const double spin_up = r.simulated_time - static_cast<double>(r.fields.turns) * period;
  if (spin_up > dc.run.duration + 0.01 * period) {
    std::snprintf(b, sizeof b,
                  "the spin-up ran %.4g s, past run.duration (%.4g s), until the flow was steady or run.max_extension "
                  "was spent; then %zu sampled turns: run.duration (--duration) is the shortest spin-up, not a limit",
                  spin_up, dc.run.duration, r.fields.turns);
    w.push_back(b);
  }
  return w;
}

nlohmann::json summary(const config::CaseFile& cf, const config::DemCase& dc, const io::DemRunResult& r) {
  const double period = dem::scene::turn_period(dc.scene);
  const double window = dc.run.flow_window_turns * period;
  const auto flows = dem::scene::window_flows(r.mass_flow, window);
  const double fed_rate = flows.fed, out_rate = flows.out;
  const auto& log = r.mass_flow;
  const auto& fields = r.fields;
  nlohmann::json j;
  j["code_version"] = centrec::io::code_version();
  j["engine"] = r.engine;
  j["engine_version"] = r.engine_version;
  j["case"] = cf.path;
  j["title"] = cf.title;
  j["mode"] = dc.scene.slice.enabled ? "slice" : "drum";
  // The drum that ran: a receiver case derives it, and then the resolved configuration omits it.
  j["drum_diameter_m"] = dc.scene.drum.diameter;
  j["drum_length_m"] = dc.scene.drum.length;
  j["drum_speed_rpm"] = coupling::rad_per_s_to_rpm(dc.scene.drum.omega);
  j["drum_tilt_deg"] = dc.scene.drum.tilt * 180.0 / M_PI;
  j["simulated_time_s"] = r.simulated_time;
  j["turns"] = r.simulated_time / period;
  j["dt_s"] = r.dt;
  j["steps"] = r.steps;
  j["threads"] = r.threads;
  j["ranks"] = r.ranks;
  j["free_particles"] = r.free_particles;
  j["glued_particles"] = r.glued_particles;
  j["holdup_kg"] = r.holdup_kg;
  const bool fed = dc.scene.feeder.enabled && !dc.scene.slice.enabled;
  // A slice has no feed and no outlet (its flow is slice_mdot_kg_s): null, not 0.
  j["target_mdot_kg_s"] = fed ? nlohmann::json(dc.scene.feeder.mass_flow) : nlohmann::json(nullptr);
  j["inlet_mdot_kg_s"] = dc.scene.slice.enabled ? nlohmann::json(nullptr) : nlohmann::json(fed_rate);
  j["outlet_mdot_kg_s"] = dc.scene.slice.enabled ? nlohmann::json(nullptr) : nlohmann::json(out_rate);
  j["flow_window_s"] = window;
  // Steady over the last flow window (dem/scene/mass_flow_window.hpp): the film a coupled
  // run may use.
  const auto steady = dem::scene::flow_steadiness(log, dc.scene, window, dc.run.steady_tolerance);
  j["steady_state"] = steady.steady;
  j["steady_flow_error"] =
      std::isfinite(steady.flow_error) ? nlohmann::json(steady.flow_error) : nlohmann::json(nullptr);
  j["steady_holdup_drift"] =
      std::isfinite(steady.holdup_drift) ? nlohmann::json(steady.holdup_drift) : nlohmann::json(nullptr);
  j["steady_tolerance"] = dc.run.steady_tolerance;
  j["steady_state_text"] = steady.describe();
  if (fed && log.size() > 2) {
    const auto ss = steady_state(log, window, dc.run.steady_tolerance);
    j["time_to_steady_state_s"] = ss.steady ? nlohmann::json(ss.time) : nlohmann::json(nullptr);
  }
  if (dc.scene.slice.enabled) {
    // Axial mass flow of the slice, mean over the flow window (and the controller's record).
    j["slice_mdot_kg_s"] = flows.axial;
    j["slice_target_mdot_kg_s"] = dc.scene.slice.target_mass_flow;
    nlohmann::json windows = nlohmann::json::array();
    for (const auto& w : r.controller)
      windows.push_back(
          {{"time_s", w.time}, {"mdot_kg_s", w.mass_flow}, {"particles", w.particles}, {"change", w.change}});
    j["controller_windows"] = windows;
  }
  j["lost_kg"] = log.empty() ? 0.0 : log.back().lost;
  j["feeder_deferred_insertions"] =
      r.feeder_deferred >= 0 ? nlohmann::json(r.feeder_deferred) : nlohmann::json(nullptr);
  j["contacts_per_particle"] =
      r.contacts_per_particle >= 0.0 ? nlohmann::json(r.contacts_per_particle) : nlohmann::json(nullptr);
  j["particle_steps_per_s"] = r.wall_time > 0.0 ? r.particle_steps / r.wall_time : 0.0;
  j["moving_particle_steps_per_s"] = r.wall_time > 0.0 && r.moving_particle_steps >= 0.0
                                         ? nlohmann::json(r.moving_particle_steps / r.wall_time)
                                         : nlohmann::json(nullptr);
  j["wall_time_s"] = r.wall_time;
  if (!r.phase_seconds.empty()) {
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, seconds] : r.phase_seconds) phases[name] = seconds;
    j["phase_wall_time_s"] = phases;
  }
  if (r.neighbour_rebuilds >= 0) {
    j["neighbour_rebuilds"] = r.neighbour_rebuilds;
    j["neighbour_list_edits"] = r.list_edits;
    j["force_pass_thread_idle_s"] = {{"pair_pass", r.pair_pass_idle}, {"parked_pass", r.parked_pass_idle}};
  }
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
  j["warnings"] = dem_run_warnings(dc, r);
  j["resolved_config"] = cf.resolved_yaml;
  return j;
}

std::string mass_flow_csv(const std::vector<dem::scene::MassFlowSample>& log) {
  std::ostringstream csv;
  // One header line of column names (pandas.read_csv reads it as is); masses are cumulative.
  csv << "time_s,fed_cumulative_kg,out_cumulative_kg,lost_cumulative_kg,holdup_kg,free_particles,slice_axial_flow_kg_"
         "s\n";
  for (const auto& s : log)
    csv << s.time << ',' << s.fed << ',' << s.out << ',' << s.lost << ',' << s.holdup << ',' << s.particles << ','
        << s.axial_flow << '\n';
  return csv.str();
}

}  // namespace

void write_dem_run_report(const std::string& out_dir, const config::CaseFile& cf, const config::DemCase& dc,
                          const io::DemRunResult& r) {
  io::write_json_file(out_dir + "/summary.json", summary(cf, dc, r));
  io::write_dem_h5(out_dir, case_provenance(cf.path, cf.resolved_yaml), dc.scene, r);
  io::write_text_atomically(out_dir + "/mass_flow.csv", mass_flow_csv(r.mass_flow));

  const double window = dc.run.flow_window_turns * dem::scene::turn_period(dc.scene);
  const auto flows = dem::scene::window_flows(r.mass_flow, window);
  const double rate = r.wall_time > 0.0 ? r.particle_steps / r.wall_time : 0.0;
  if (dc.scene.slice.enabled)
    std::printf("holdup %.4f kg (%lld free particles), slice axial flow %.3f g/s over the last %.2f s\n", r.holdup_kg,
                static_cast<long long>(r.free_particles), flows.axial * 1e3, window);
  else
    std::printf("holdup %.4f kg (%lld free particles), inlet %.3f g/s, outlet %.3f g/s over the last %.2f s\n",
                r.holdup_kg, static_cast<long long>(r.free_particles), flows.fed * 1e3, flows.out * 1e3, window);
  std::printf("%.3g particle-steps/s, wall time %.1f s\n", rate, r.wall_time);
  if (r.wall_time > 0.0 && r.moving_particle_steps >= 0.0 && r.glued_particles > 0)
    std::printf("%.3g particle-steps/s counting the free particles only (%lld glued left out)\n",
                r.moving_particle_steps / r.wall_time, static_cast<long long>(r.glued_particles));
  if (!r.phase_seconds.empty() && r.wall_time > 0.0) {
    std::string line = "phases:";
    for (const auto& [name, seconds] : r.phase_seconds) {
      char b[96];
      std::snprintf(b, sizeof b, " %s %.1f s (%.0f %%),", name.c_str(), seconds, 100.0 * seconds / r.wall_time);
      line += b;
    }
    line.back() = '\n';
    std::fputs(line.c_str(), stdout);
    if (r.neighbour_rebuilds >= 0)
      std::printf(
          "neighbour lists: %lld rebuilds (one per %.0f steps), %lld insertions/removals worked in without one\n",
          static_cast<long long>(r.neighbour_rebuilds),
          r.neighbour_rebuilds > 0 ? static_cast<double>(r.steps) / static_cast<double>(r.neighbour_rebuilds) : 0.0,
          static_cast<long long>(r.list_edits));
    if (r.threads > 1)
      std::printf("force pass: threads waited %.1f s in the pair pass and %.1f s in the parked pass for the slowest\n",
                  r.pair_pass_idle, r.parked_pass_idle);
  }
  if (r.fields.snapshots > 0)
    std::printf("film thickness %.2f +- %.2f d over %zu turns\n", r.fields.mean_thickness.mean_d,
                r.fields.mean_thickness.std_d, r.fields.turns);
  std::printf("wrote %s/{summary.json,dem.h5,dem.xmf,drum.xmf,mass_flow.csv}\n", out_dir.c_str());
  std::printf("steady state: %s (tolerance %.0f %%, dem.run.steady_tolerance)\n",
              dem::scene::flow_steadiness(r.mass_flow, dc.scene, window, dc.run.steady_tolerance).describe().c_str(),
              100.0 * dc.run.steady_tolerance);
  for (const std::string& w : dem_run_warnings(dc, r)) std::fprintf(stderr, "centrec dem: WARNING: %s\n", w.c_str());
}

}  // namespace centrec::runs
