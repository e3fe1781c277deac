#include "dem_film_averages.hpp"

#include <stdexcept>
#include <string>

namespace centrec::coupling {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("DEM film averages: " + what);
}
}  // namespace

void DemFilmAverages::check() const {
  require(drum_radius > 0.0 && length > 0.0 && particle_diameter > 0.0 && particle_density > 0.0,
          "drum radius, length, particle diameter and density must be > 0");
  require(mdot > 0.0, "the DEM's outlet mass flow must be > 0 (did the run reach the outlet?), got " +
                          std::to_string(mdot) + " kg/s");
  require(!section_z.empty() && thickness.size() == section_z.size() && thickness_std.size() == section_z.size(),
          "need one thickness (and std) per axial section");
  require(!bin_theta.empty() && surface_velocity.size() == bin_theta.size() &&
              moving_zone_of_bin.size() == bin_theta.size(),
          "need one surface velocity and zone label per tangential bin");
  const std::size_t nb = wall_distance_d.size();
  require(nb >= 2, "need at least two wall-distance bins");
  require(!arc_theta.empty() && arc_z_over_length.size() == arc_theta.size() && u_mean.size() == arc_theta.size() &&
              u_std.size() == arc_theta.size() && u_turns.size() == arc_theta.size(),
          "need one velocity profile (mean, std, turns) per arc section");
  for (std::size_t a = 0; a < arc_theta.size(); ++a)
    require(u_mean[a].size() == nb && u_std[a].size() == nb && u_turns[a].size() == nb,
            "velocity profile " + std::to_string(a) + " has the wrong number of bins");
  require(phi_stationary.size() == nb && phi_moving.size() == nb && phi_stationary_std.size() == nb &&
              phi_moving_std.size() == nb,
          "solid fraction needs one value per wall-distance bin and zone");
  require(phi_glued.empty() || phi_glued.size() == nb, "glued-layer solid fraction needs one value per bin");
  require(dispersion.size() == nb && dispersion_std.size() == nb, "dispersion needs one value per bin");
  for (double t : thickness) require(t > 0.0, "film thickness must be > 0 in every section (is the film empty?)");
}

}  // namespace centrec::coupling
