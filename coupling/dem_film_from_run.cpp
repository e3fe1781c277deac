#include "coupling/dem_film_from_run.hpp"

#include <stdexcept>

#include "coupling/glued_layer.hpp"
#include "dem/scene/mass_flow_window.hpp"

namespace centrec::coupling {

namespace {
// [rows][bins] profile bins -> the mean and standard deviation matrices.
void split_profiles(const std::vector<std::vector<film::ProfileBin>>& p, std::vector<std::vector<double>>& mean,
                    std::vector<std::vector<double>>& sd) {
  for (const auto& row : p) {
    mean.emplace_back();
    sd.emplace_back();
    for (const auto& b : row) {
      mean.back().push_back(b.mean);
      sd.back().push_back(b.stddev);
    }
  }
}
}  // namespace

DemFilmAverages dem_film_averages(const dem::scene::SampledFilm& ff, const dem::scene::SceneConfig& scene,
                                  const std::vector<dem::scene::MassFlowSample>& mass_flow, double flow_window_turns,
                                  double steady_tolerance) {
  if (ff.snapshots == 0)
    throw std::invalid_argument("no film fields (the DEM case needs sampling.turns > 0 for film fields)");
  if (mass_flow.size() < 2) throw std::invalid_argument("the mass-flow record has fewer than two samples");
  DemFilmAverages a;
  a.drum_radius = 0.5 * scene.drum.diameter;
  a.particle_diameter = scene.particle.diameter;
  a.length = scene.drum.length;
  a.omega = scene.drum.omega;
  a.particle_density = scene.particle.material.density;
  a.slice = scene.slice.enabled;
  if (!a.slice && scene.feeder.enabled) a.feed_end = scene.feeder.axial_start + scene.feeder.axial_length;
  a.sampled_turns = static_cast<double>(ff.turns);
  const auto flow = dem::scene::flow_steadiness(mass_flow, scene, flow_window_turns * dem::scene::turn_period(scene),
                                                steady_tolerance);
  a.mdot = flow.measured;
  a.mdot_target = flow.target;
  a.steady = flow.steady;
  a.steady_text = flow.describe();

  // A slice stands for the drum's developed middle: its one section sits at mid-length.
  a.section_z = a.slice ? std::vector<double>{0.5 * a.length} : ff.section_z;
  for (const auto& s : ff.section_thickness) {
    a.thickness.push_back(s.mean_m);
    a.thickness_std.push_back(s.std_m);
  }
  double moving = 0.0;
  for (int z : ff.zones.zone_of_bin) moving += z > 0 ? 1.0 : 0.0;
  a.moving_fraction = ff.zones.zone_of_bin.empty() ? 0.0 : moving / static_cast<double>(ff.zones.zone_of_bin.size());
  a.wall_distance_d = ff.bin_centre_d;
  a.ring_z = a.slice ? std::vector<double>{0.5 * a.length} : ff.ring_z;
  split_profiles(ff.ring_solid_fraction, a.ring_phi, a.ring_phi_std);
  split_profiles(ff.ring_volume_flux, a.ring_flux, a.ring_flux_std);
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
