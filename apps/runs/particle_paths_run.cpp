#include "runs/particle_paths_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "coupling/particle_path_heating.hpp"
#include "dem/film/particle_tracks.hpp"
#include "io/atomic_write.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "io/particle_tracks_h5.hpp"
#include "io/summary_json.hpp"

namespace centrec::runs {

namespace {

struct WeightedStats {
  double mean = 0.0, std = 0.0, q05 = 0.0, q50 = 0.0, q95 = 0.0, max = 0.0;
};

WeightedStats stats(const std::vector<double>& v, const std::vector<double>& w) {
  WeightedStats s;
  double sw = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    s.mean += w[i] * v[i];
    sw += w[i];
    s.max = i == 0 ? v[i] : std::max(s.max, v[i]);
  }
  s.mean /= sw;
  for (std::size_t i = 0; i < v.size(); ++i) s.std += w[i] * (v[i] - s.mean) * (v[i] - s.mean);
  s.std = std::sqrt(s.std / sw);
  s.q05 = film::weighted_quantile(v, w, 0.05);
  s.q50 = film::weighted_quantile(v, w, 0.50);
  s.q95 = film::weighted_quantile(v, w, 0.95);
  return s;
}

nlohmann::json to_json(const WeightedStats& s) {
  return {{"mean", s.mean}, {"std", s.std}, {"q05", s.q05}, {"q50", s.q50}, {"q95", s.q95}, {"max", s.max}};
}

}  // namespace

nlohmann::json particle_paths_report(const std::string& dem_dir, const std::string& results_h5,
                                     const config::ThermalCase& tc, const std::string& out_dir) {
  const nlohmann::json dem = io::read_json_file(dem_dir + "/summary.json");
  if (dem.value("mode", "") == "slice")
    throw std::runtime_error(dem_dir + " is a periodic slice: residence times and paths need a fed drum");
  const double R = 0.5 * dem.at("drum_diameter_m").get<double>(), L = dem.at("drum_length_m").get<double>();
  const std::vector<film::TrackSnapshot> tracks = io::read_tracks(dem_dir);
  if (tracks.size() < 3)
    throw std::runtime_error(dem_dir + " holds " + std::to_string(tracks.size()) +
                             " tracked snapshots (tracks/): a fed drum's sampled turns write them");
  const std::vector<film::ParticlePath> paths = film::complete_paths(tracks);
  const film::ResidenceTimes rt = film::residence_times(tracks, paths);
  std::size_t weighed = 0;
  for (const double w : rt.weight) weighed += w > 0.0;
  if (weighed == 0)
    throw std::runtime_error(dem_dir + ": no particle was fed and left inside the tracks' " +
                             std::to_string(rt.window) + " s (" + std::to_string(rt.fed) + " fed, " +
                             std::to_string(rt.left) + " left): sample more turns than a residence time");

  // The thermal solution on its grid, and the film it ran on.
  const io::H5File f = io::H5File::open_read(results_h5);
  const thermal::FilmField film = io::read_film_field(f, "/film");
  std::vector<std::size_t> dims;
  coupling::FilmTemperatureField field;
  field.length = film.length;
  field.z = f.read("/grid/z");
  field.thickness = f.read("/grid/thickness");
  field.T = f.read("/steady/T", &dims);
  if (dims.size() != 2 || dims[0] != field.z.size())
    throw std::runtime_error(results_h5 + ": /steady/T is not [nz, nxi]");
  field.nxi = static_cast<int>(dims[1]);
  const std::vector<double> k_bed = f.read("/steady/k_bed"), k_rad = f.read("/steady/k_rad"), phi = f.read("/grid/phi");
  field.k_conduction.resize(k_bed.size());
  for (std::size_t i = 0; i < k_bed.size(); ++i) field.k_conduction[i] = k_bed[i] + k_rad[i];
  const double T_mix = f.number_attribute("/steady", "T_out_K");

  coupling::PathHeatingSpec spec;
  spec.drum_radius = R;
  spec.scale = film.length / L;
  spec.T_in = tc.model.T_in;
  spec.material = tc.model.material;
  spec.heat = tc.model.heat;
  const std::vector<coupling::HeatedPath> relaxed = coupling::heat_paths(paths, rt.weight, tracks, field, spec);
  spec.relax = false;
  const std::vector<coupling::HeatedPath> field_read = coupling::heat_paths(paths, rt.weight, tracks, field, spec);

  // The mean residence the continuum film implies: its mass over its flow (the grid's
  // stripes, perimeter pi D_f, the imposed flow), in the receiver and in the drum's time.
  double mass_per_width = 0.0;
  const double dz = field.length / static_cast<double>(field.z.size());
  for (std::size_t i = 0; i < field.z.size(); ++i)
    for (int j = 0; j < field.nxi; ++j)
      mass_per_width += tc.model.material.rho_s *
                        phi[i * static_cast<std::size_t>(field.nxi) + static_cast<std::size_t>(j)] *
                        field.thickness[i] / field.nxi * dz;
  const double D_f = f.number_attribute("/coupling", "planar_diameter_m"),
               mdot = f.number_attribute("/coupling", "imposed_mdot_kg_s");
  // The film's mass holds the glued wall layer (added back at rest by the mapping, its
  // volume exact: docs/coupling.md); the flowing particles' residence leaves it out: the
  // DEM's glued mass over its feed, in the receiver's time.
  const double feed = dem.at("inlet_mdot_kg_s").get<double>(), holdup = dem.at("holdup_kg").get<double>();
  const double d = tc.model.material.d, m_p = tc.model.material.rho_s * M_PI * d * d * d / 6.0;
  const double glued_kg = dem.at("glued_particles").get<double>() * m_p;
  const double tau_film_all = mass_per_width * M_PI * D_f / mdot;
  const double tau_film = tau_film_all - spec.scale * glued_kg / feed;
  const double tau_little = holdup / feed;

  std::vector<double> tau_r, w, T_relax, T_field, T_peak;
  for (std::size_t i = 0; i < relaxed.size(); ++i) {
    tau_r.push_back(relaxed[i].residence);
    w.push_back(relaxed[i].weight);
    T_relax.push_back(relaxed[i].T_out);
    T_field.push_back(field_read[i].T_out);
    T_peak.push_back(relaxed[i].T_peak);
  }
  const WeightedStats rs = stats(rt.tau, rt.weight), ts = stats(T_relax, w), fs = stats(T_field, w),
                      ps = stats(T_peak, w);
  const double fast = 0.2;  // s in the drum: the feed stream's crossing (docs/slice_vs_drum_dd80.md)
  nlohmann::json j;
  j["dem_run"] = dem_dir;
  j["results"] = results_h5;
  j["tracked_snapshots"] = tracks.size();
  j["window_s"] = rt.window;
  j["snapshot_spacing_s"] = rt.resolution;
  j["fed_in_window"] = rt.fed;
  j["left_in_window"] = rt.left;
  j["complete_paths"] = paths.size();
  j["weighted_coverage"] = rt.coverage();
  j["scale_receiver_over_drum"] = spec.scale;
  j["residence_drum_s"] = to_json(rs);
  j["residence_share_below_0.2s"] = rt.share_below(fast);
  j["mean_residence_little_s"] = tau_little;
  j["mean_residence_film_implies_drum_s"] = tau_film / spec.scale;
  j["mean_residence_film_implies_receiver_s"] = tau_film;
  j["film_mass_over_dem_mass"] = tau_film_all / (spec.scale * (holdup + glued_kg) / feed);
  j["T_out_mixing_cup_K"] = T_mix;
  j["T_out_paths_K"] = to_json(ts);
  j["T_out_paths_tau0_K"] = to_json(fs);
  j["T_peak_paths_K"] = to_json(ps);
  const std::vector<double> T_surface = f.read("/steady/T_surface");
  j["T_surface_max_K"] = *std::max_element(T_surface.begin(), T_surface.end());

  std::ostringstream csv;
  csv << "residence_receiver_s,weight,T_out_K,T_out_tau0_K,T_peak_K\n";
  for (std::size_t i = 0; i < relaxed.size(); ++i)
    csv << tau_r[i] << ',' << w[i] << ',' << T_relax[i] << ',' << T_field[i] << ',' << T_peak[i] << '\n';
  io::write_text_atomically(out_dir + "/paths.csv", csv.str());

  std::printf(
      "particle tracks: %zu snapshots over %.3f s (every %.4f s); %zu fed and %zu left in the window, "
      "%zu paths complete (weighted coverage of the feed %.3f)\n",
      tracks.size(), rt.window, rt.resolution, rt.fed, rt.left, paths.size(), rt.coverage());
  std::printf(
      "residence in the drum: mean %.3f s (holdup / feed %.3f s; the thermal film implies %.3f s, its mass %.3f x the "
      "DEM's with the glued layer), 5/50/95 %% %.3f / %.3f / %.3f s, %.1f %% below %.1f s\n",
      rs.mean, tau_little, tau_film / spec.scale, j["film_mass_over_dem_mass"].get<double>(), rs.q05, rs.q50, rs.q95,
      100.0 * rt.share_below(fast), fast);
  std::printf(
      "outlet temperature of the particles (receiver, x %.4g in z and t): mean %.2f K (mixing cup %.2f K), "
      "std %.2f K, 5/50/95 %% %.2f / %.2f / %.2f K, max %.2f K\n",
      spec.scale, ts.mean, T_mix, ts.std, ts.q05, ts.q50, ts.q95, ts.max);
  std::printf("  read from the field at every point (tau = 0): mean %.2f K, std %.2f K, 5/95 %% %.2f / %.2f K\n",
              fs.mean, fs.std, fs.q05, fs.q95);
  std::printf("peak particle temperature on the way: 95 %% %.2f K, max %.2f K; the film surface's max %.2f K\n", ps.q95,
              ps.max, j["T_surface_max_K"].get<double>());
  return j;
}

}  // namespace centrec::runs
