#include "coupling/dem_film_from_run.hpp"

#include <stdexcept>

#include "coupling/glued_layer.hpp"
#include "dem/scene/mass_flow_window.hpp"

namespace centrec::coupling {

namespace {
// [rows][bins] profile bins -> the mean, standard deviation and period-count matrices.
void split_profiles(const std::vector<std::vector<film::ProfileBin>>& p, std::vector<std::vector<double>>& mean,
                    std::vector<std::vector<double>>& sd, std::vector<std::vector<double>>* periods) {
  for (const auto& row : p) {
    mean.emplace_back();
    sd.emplace_back();
    if (periods) periods->emplace_back();
    for (const auto& b : row) {
      mean.back().push_back(b.mean);
      sd.back().push_back(b.stddev);
      if (periods) periods->back().push_back(static_cast<double>(b.periods));
    }
  }
}
}  // namespace

DemFilmAverages dem_film_averages(const dem::scene::FilmFields& ff, const dem::scene::SceneConfig& scene,
                                  const std::vector<dem::scene::MassFlowSample>& mass_flow, double flow_window_turns) {
  if (ff.snapshots == 0)
    throw std::invalid_argument("no film fields (the DEM case needs sampling.turns > 0 for film fields)");
  if (mass_flow.size() < 2) throw std::invalid_argument("the mass-flow record has fewer than two samples");
  DemFilmAverages a;
  a.drum_radius = 0.5 * scene.drum.diameter;
  a.particle_diameter = scene.particle.diameter;
  a.length = scene.drum.length;
  a.omega = scene.drum.omega;
  a.particle_density = scene.particle.material.density;
  a.sampled_turns = static_cast<double>(ff.turns);
  // Outlet mass flow over the last flow window (as `centrec dem` reports it).
  a.mdot = dem::scene::window_flows(mass_flow, flow_window_turns * dem::scene::turn_period(scene)).out;

  a.section_z = ff.section_z;
  for (const auto& s : ff.section_thickness) {
    a.thickness.push_back(s.mean_m);
    a.thickness_std.push_back(s.std_m);
  }
  a.bin_theta = ff.bin_theta;
  a.surface_velocity = ff.surface_velocity;
  for (int z : ff.zones.zone_of_bin) a.moving_zone_of_bin.push_back(z > 0 ? 1 : 0);
  a.wall_distance_d = ff.bin_centre_d;
  for (const auto& arc : ff.arcs) {
    a.arc_theta.push_back(arc.theta);
    a.arc_z_over_length.push_back(arc.z_over_length);
  }
  split_profiles(ff.velocity_profiles, a.u_mean, a.u_std, &a.u_turns);
  std::vector<std::vector<double>> phi, phi_sd;
  split_profiles(ff.solid_fraction, phi, phi_sd, nullptr);
  if (phi.size() != 2) throw std::invalid_argument("the solid fraction needs 2 rows (stationary, moving)");
  a.phi_stationary = phi[0], a.phi_moving = phi[1];
  a.phi_stationary_std = phi_sd[0], a.phi_moving_std = phi_sd[1];
  if (scene.rough_wall.enabled)
    a.phi_glued = glued_layer_solid_fraction(scene, a.drum_radius, a.wall_distance_d, a.bin_width_d(),
                                             a.particle_diameter);
  for (const auto& b : ff.dispersion) {
    a.dispersion.push_back(b.coefficient);
    a.dispersion_std.push_back(b.coefficient_std);
  }
  a.check();
  return a;
}

}  // namespace centrec::coupling
