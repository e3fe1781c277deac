#include "io/dem_film_h5.hpp"

#include <stdexcept>
#include <utility>

#include "coupling/dem_film_from_run.hpp"
#include "io/dem_output_h5.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

namespace {
// [rows][bins] profile bins from the _mean, _std and _turns datasets of a profile.
std::vector<std::vector<film::ProfileBin>> read_profiles(const H5File& f, const std::string& path) {
  std::vector<std::size_t> dims, sd_dims;
  const std::vector<double> mean = f.read(path + "_mean", &dims), sd = f.read(path + "_std", &sd_dims);
  if (dims.size() != 2 || sd_dims != dims) throw std::runtime_error(path + "_mean and _std must be 2D of one shape");
  const std::vector<double> turns = f.read(path + "_turns");
  if (turns.size() != mean.size()) throw std::runtime_error(path + "_turns differs in shape");
  std::vector<std::vector<film::ProfileBin>> p(dims[0], std::vector<film::ProfileBin>(dims[1]));
  for (std::size_t r = 0, k = 0; r < dims[0]; ++r)
    for (std::size_t c = 0; c < dims[1]; ++c, ++k) {
      p[r][c].mean = mean[k];
      p[r][c].stddev = sd[k];
      p[r][c].periods = static_cast<std::size_t>(turns[k]);
    }
  return p;
}

// Two 1D datasets of one length (a quantity and its spread, or two coordinates of a point).
std::pair<std::vector<double>, std::vector<double>> read_pair(const H5File& f, const std::string& a,
                                                              const std::string& b) {
  std::pair<std::vector<double>, std::vector<double>> p{f.read(a), f.read(b)};
  if (p.first.size() != p.second.size()) throw std::runtime_error(a + " and " + b + " differ in length");
  return p;
}

// The film fields as apps/io/dem_output_h5 wrote them (what the coupling uses of them).
dem::scene::FilmFields read_film_fields(const H5File& f) {
  dem::scene::FilmFields ff;
  ff.turns = static_cast<std::size_t>(f.number_attribute("/film", "sampled_turns"));
  ff.snapshots = static_cast<std::size_t>(f.number_attribute("/film", "snapshots"));
  ff.section_z = f.read("/film/section_z");
  const auto [tm, ts] = read_pair(f, "/film/thickness_mean", "/film/thickness_std");
  ff.section_thickness.resize(tm.size());
  for (std::size_t k = 0; k < tm.size(); ++k) ff.section_thickness[k].mean_m = tm[k], ff.section_thickness[k].std_m = ts[k];
  ff.bin_theta = f.read("/film/bin_theta");
  ff.surface_velocity = f.read("/film/surface_axial_velocity");
  for (double z : f.read("/film/moving_zone_of_bin")) ff.zones.zone_of_bin.push_back(z > 0.5 ? 1 : 0);
  ff.bin_centre_d = f.read("/film/wall_distance_d");
  const auto [dc, ds] = read_pair(f, "/film/dispersion", "/film/dispersion_std");
  ff.dispersion.resize(dc.size());
  for (std::size_t k = 0; k < dc.size(); ++k) ff.dispersion[k].coefficient = dc[k], ff.dispersion[k].coefficient_std = ds[k];
  ff.ring_z = f.read("/film/ring_z");
  ff.ring_solid_fraction = read_profiles(f, "/film/ring_solid_fraction");
  ff.ring_volume_flux = read_profiles(f, "/film/ring_volume_flux");
  return ff;
}
}  // namespace

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
