#include "dem_film_averages.hpp"

#include <stdexcept>
#include <string>

namespace centrec::coupling {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("DEM film averages: " + what);
}

void require_rows(const std::vector<std::vector<double>>& rows, std::size_t n_rows, std::size_t n_bins,
                  const std::string& name) {
  require(rows.size() == n_rows, name + " needs one row per axial section");
  for (const auto& r : rows) require(r.size() == n_bins, name + " has a row with the wrong number of bins");
}
}  // namespace

void DemFilmAverages::check() const {
  require(drum_radius > 0.0 && length > 0.0 && particle_diameter > 0.0 && particle_density > 0.0,
          "drum radius, length, particle diameter and density must be > 0");
  require(mdot > 0.0, std::string("the DEM's measured mass flow must be > 0 (") +
                          (slice ? "did the slice's film flow?" : "did the run reach the outlet?") + "), got " +
                          std::to_string(mdot) + " kg/s");
  require(!section_z.empty() && thickness.size() == section_z.size() && thickness_std.size() == section_z.size(),
          "need one thickness (and std) per axial section");
  const std::size_t nb = wall_distance_d.size();
  require(nb >= 2, "need at least two wall-distance bins");
  require(!ring_z.empty(), "need the full-circumference profiles (dem.h5 /film/ring_*)");
  for (const auto* rows : {&ring_phi, &ring_phi_std, &ring_flux, &ring_flux_std})
    require_rows(*rows, ring_z.size(), nb, "a full-circumference profile");
  require(phi_glued.empty() || phi_glued.size() == nb, "glued-layer solid fraction needs one value per bin");
  require(dispersion.size() == nb && dispersion_std.size() == nb, "dispersion needs one value per bin");
  for (double t : thickness) require(t > 0.0, "film thickness must be > 0 in every section (is the film empty?)");
}

}  // namespace centrec::coupling
