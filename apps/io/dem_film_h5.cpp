#include "io/dem_film_h5.hpp"

#include <stdexcept>

#include "coupling/glued_layer.hpp"
#include "dem/scene/mass_flow_window.hpp"
#include "io/dem_output_h5.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

namespace {
// [rows][cols] matrix from a 2D dataset.
std::vector<std::vector<double>> read_matrix(const H5File& f, const std::string& path) {
  std::vector<std::size_t> dims;
  const std::vector<double> v = f.read(path, &dims);
  if (dims.size() != 2) throw std::runtime_error(f.path() + ": " + path + " must be 2D");
  std::vector<std::vector<double>> m(dims[0]);
  for (std::size_t r = 0; r < dims[0]; ++r) m[r].assign(v.begin() + r * dims[1], v.begin() + (r + 1) * dims[1]);
  return m;
}
}  // namespace

coupling::DemFilmAverages read_dem_film(const std::string& path, const dem::scene::SceneConfig& scene,
                                        double flow_window_turns) {
  const H5File f = H5File::open_read(path);
  if (!f.exists("/film"))
    throw std::runtime_error(path + ": no /film group (the DEM case needs sampling.turns > 0 for film fields)");
  coupling::DemFilmAverages a;
  try {
    a.drum_radius = f.number_attribute("/", "drum_radius_m");
    a.particle_diameter = f.number_attribute("/", "particle_diameter_m");
    a.length = scene.drum.length;
    a.omega = scene.drum.omega;
    a.particle_density = scene.particle.material.density;
    a.sampled_turns = f.number_attribute("/film", "sampled_turns");
    // Outlet mass flow over the last flow window (as `centrec dem` reports it).
    const auto log = read_mass_flow_log(f);
    if (log.size() < 2) throw std::runtime_error("/mass_flow has fewer than two samples");
    a.mdot = dem::scene::window_flows(log, flow_window_turns * f.number_attribute("/", "turn_period_s")).out;

    a.section_z = f.read("/film/section_z");
    a.thickness = f.read("/film/thickness_mean");
    a.thickness_std = f.read("/film/thickness_std");
    a.bin_theta = f.read("/film/bin_theta");
    a.surface_velocity = f.read("/film/surface_axial_velocity");
    for (double z : f.read("/film/moving_zone_of_bin")) a.moving_zone_of_bin.push_back(z > 0.5 ? 1 : 0);
    a.wall_distance_d = f.read("/film/wall_distance_d");
    a.arc_theta = f.read("/film/arc_theta");
    a.arc_z_over_length = f.read("/film/arc_z_over_length");
    a.u_mean = read_matrix(f, "/film/axial_velocity_mean");
    a.u_std = read_matrix(f, "/film/axial_velocity_std");
    a.u_turns = read_matrix(f, "/film/axial_velocity_turns");
    const auto phi = read_matrix(f, "/film/solid_fraction_mean"), phi_sd = read_matrix(f, "/film/solid_fraction_std");
    if (phi.size() != 2 || phi_sd.size() != 2)
      throw std::runtime_error("/film/solid_fraction_* must have 2 rows (stationary, moving)");
    a.phi_stationary = phi[0], a.phi_moving = phi[1];
    a.phi_stationary_std = phi_sd[0], a.phi_moving_std = phi_sd[1];
    if (scene.rough_wall.enabled)
      a.phi_glued = coupling::glued_layer_solid_fraction(scene, a.drum_radius, a.wall_distance_d, a.bin_width_d(),
                                                         a.particle_diameter);
    a.dispersion = f.read("/film/dispersion");
    a.dispersion_std = f.read("/film/dispersion_std");
    a.check();
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return a;
}

}  // namespace centrec::io
