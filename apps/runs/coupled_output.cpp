#include "runs/coupled_output.hpp"

#include <algorithm>

#include "config/case_checks.hpp"
#include "io/atomic_write.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "runs/thermal_output.hpp"

namespace centrec::runs {

namespace {
void write_coupling_group(io::H5File& f, const CoupledRun& r) {
  f.create_group("/coupling");
  f.set_attribute("/coupling", "film_source", r.thermal.film_source.text());
  if (!r.film_from_dem()) return;
  const auto& c = r.closure;
  const auto& m = r.imposed;
  f.set_attribute("/coupling", "dem_cache_key", r.cache_key);
  f.set_attribute("/coupling", "dem_measured_mdot_kg_s", r.averages.mdot);
  f.set_attribute("/coupling", "dem_target_mdot_kg_s", r.averages.mdot_target);
  f.set_attribute("/coupling", "dem_steady", r.averages.steady ? 1.0 : 0.0);
  f.set_attribute("/coupling", "dem_steady_state", r.averages.steady_text);
  f.set_attribute("/coupling", "film_mapping", r.mapping.mapping);
  for (const auto& fig : r.mapping.figures) f.set_attribute("/coupling", fig.name, fig.value);
  f.set_attribute("/coupling", "flow_closure_mean", c.mean_over_measured);
  f.set_attribute("/coupling", "flow_closure_worst_error", c.worst_error);
  f.set_attribute("/coupling", "imposed_mdot_kg_s", m.mdot);
  f.set_attribute("/coupling", "imposed_velocity_factor", m.factor);
  f.set_attribute("/coupling", "drum_radius_m", m.drum_radius);
  f.set_attribute("/coupling", "mean_flux_depth_m", m.mean_flux_depth);
  f.set_attribute("/coupling", "planar_diameter_m", m.planar_diameter);
  f.set_attribute("/coupling", "moving_fraction", r.averages.moving_fraction);
  f.set_attribute("/coupling", "scaling", r.thermal.film.scaling);
  f.write("/coupling/flow_closure", c.section_over_measured, "1");
  for (const auto& p : r.mapping.profiles) f.write("/coupling/" + p.name, p.values, p.unit);
  f.write("/coupling/dem_section_z", r.averages.section_z, "m");
  f.write("/coupling/dem_thickness", r.averages.thickness, "m");
  f.write("/coupling/dem_thickness_std", r.averages.thickness_std, "m");
  for (const char* name : {"dem_thickness", "dem_thickness_std"})
    f.attach_scale(std::string("/coupling/") + name, 0, "/coupling/dem_section_z", "z");
}
}  // namespace

void write_coupled_h5(const std::string& dir, const CoupledRun& r, const io::Provenance& p) {
  io::H5File f = io::H5File::create(dir + "/results.h5");
  write_thermal_groups(f, r.thermal, r.result, p);
  write_coupling_group(f, r);
  f.commit();
  io::write_text_atomically(dir + "/results.xmf", thermal_xdmf("results.h5", r.result));
  io::write_text_atomically(dir + "/along_z.csv", along_z_csv(r.result));
  io::write_text_atomically(dir + "/film_profiles.csv", film_profiles_csv(r.thermal.film));
  io::H5File film = io::H5File::create(dir + "/film.h5");
  io::write_provenance(film, p);
  film.set_attribute("/", "film_source", r.thermal.film_source.text());
  io::write_film_field(film, r.thermal.film, "/film");
  film.commit();
}

FilmThickness film_thickness(const CoupledRun& r) {
  const thermal::FilmField& f = r.thermal.film;
  const double d = f.particle_diameter > 0.0 ? f.particle_diameter : r.thermal.model.material.d;
  double t_sum = 0.0;
  for (double t : f.t) t_sum += t;
  FilmThickness t;
  t.mean_m = t_sum / f.t.size();
  t.mean_d = t_sum / f.t.size() / d;
  t.min_d = *std::min_element(f.t.begin(), f.t.end()) / d;
  t.max_d = *std::max_element(f.t.begin(), f.t.end()) / d;
  return t;
}

nlohmann::json coupled_summary(const CoupledRun& r) {
  nlohmann::json j = thermal_summary(r.thermal, r.result);
  const thermal::FilmField& f = r.thermal.film;
  const FilmThickness t = film_thickness(r);
  j["film"] = {{"source", r.thermal.film_source.text()},
               {"mean_thickness_m", t.mean_m},
               {"mean_thickness_d", t.mean_d},
               {"min_thickness_d", t.min_d},
               {"max_thickness_d", t.max_d},
               {"length_m", f.length},
               {"mdot_kg_s", f.mdot},
               {"scaling", f.scaling}};
  j["wall_time_s"] = {{"dem", r.dem_seconds},
                      {"coupling", r.mapping_seconds},
                      {"thermal", r.thermal_seconds},
                      {"total", r.dem_seconds + r.mapping_seconds + r.thermal_seconds}};
  if (!r.film_from_dem()) return j;
  const auto& c = r.closure;
  const auto& m = r.imposed;
  const auto& sd = r.dem.scene;
  j["point"]["speed_rpm"] = coupling::rad_per_s_to_rpm(r.has_receiver ? r.receiver.op.omega : sd.drum.omega);
  j["point"]["seed"] = sd.seed;
  j["point"]["dt_s"] = config::dem_time_step(r.dem);
  j["dem"] = {{"cached", r.dem_cached},
              {"given", r.dem_given},
              {"resumed_from", r.dem_resumed_from},
              {"cache_key", r.cache_key},
              {"dir", r.dem_dir},
              {"mode", sd.slice.enabled ? "slice" : "drum"},
              {"drum_diameter_m", sd.drum.diameter},
              {"drum_diameter_over_d", sd.drum.diameter / sd.particle.diameter},
              {"drum_length_m", sd.drum.length},
              {"speed_rpm", coupling::rad_per_s_to_rpm(sd.drum.omega)},
              {"target_mdot_kg_s", r.averages.mdot_target},
              {"measured_mdot_kg_s", r.averages.mdot},
              {"steady", r.averages.steady},
              {"steady_state", r.averages.steady_text},
              {"moving_fraction", r.averages.moving_fraction},
              {"sampled_turns", r.averages.sampled_turns},
              {"summary", r.dem_summary}};
  j["coupling"] = {{"film_mapping", r.mapping.mapping},
                   {"flow_closure_mean", c.mean_over_measured},
                   {"flow_closure_min", c.min_over_measured},
                   {"flow_closure_max", c.max_over_measured},
                   {"flow_closure_tolerance", coupling::kFlowClosureTolerance},
                   {"imposed_mdot_kg_s", m.mdot},
                   {"imposed_velocity_factor", m.factor},
                   {"mean_flux_depth_m", m.mean_flux_depth},
                   {"planar_diameter_m", m.planar_diameter}};
  for (const auto& fig : r.mapping.figures) j["coupling"][fig.name] = fig.value;
  for (const auto& p : r.mapping.profiles) {
    if (!p.min_as.empty()) j["coupling"][p.min_as] = *std::min_element(p.values.begin(), p.values.end());
    if (!p.max_as.empty()) j["coupling"][p.max_as] = *std::max_element(p.values.begin(), p.values.end());
  }
  for (const std::string& w : r.warnings) j["warnings"].push_back(w);
  if (r.has_receiver) {
    const auto& s = r.scale;
    j["scaling"] = {{"receiver_diameter_m", r.receiver.op.diameter},
                    {"receiver_length_m", r.receiver.op.length},
                    {"receiver_speed_rpm", coupling::rad_per_s_to_rpm(r.receiver.op.omega)},
                    {"receiver_mdot_kg_s", r.receiver.op.mass_flow},
                    {"dem_derived", r.receiver.dem_diameter_d > 0.0},
                    {"length_ratio", s.length_ratio},
                    {"radius_ratio", s.radius_ratio},
                    {"omega_ratio", s.omega_ratio},
                    {"mdot_ratio", s.mdot_ratio},
                    {"eq1_error", s.eq1_error},
                    {"eq2_error", s.eq2_error},
                    {"eq3_error", s.eq3_error},
                    {"description", s.description}};
  }
  return j;
}

}  // namespace centrec::runs
