#include "io/dem_film_h5.hpp"

#include <stdexcept>

#include "coupling/dem_film_from_run.hpp"
#include "io/dem_output_h5.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

coupling::DemFilmAverages read_dem_film(const std::string& path, const dem::scene::SceneConfig& scene,
                                        double flow_window_turns, double steady_tolerance) {
  const H5File f = H5File::open_read(path);
  if (!f.exists("/film"))
    throw std::runtime_error(path + ": no /film group (the DEM case needs sampling.turns > 0 for film fields)");
  try {
    return coupling::dem_film_averages(read_film_fields(f), scene, read_mass_flow_log(f), flow_window_turns,
                                       steady_tolerance);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace centrec::io
