#include "film_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace centrec::coupling {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Empty bins (NaN) take the nearest sampled bin's value; `wall_value` (if finite) replaces
// the empties below the first sampled bin instead. Returns how many bins were filled.
int fill_empty(std::vector<double>& v, double wall_value) {
  std::vector<std::size_t> valid;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::isfinite(v[k])) valid.push_back(k);
  if (valid.empty()) throw std::invalid_argument("film mapping: a DEM profile has no sampled bin at all");
  int filled = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (std::isfinite(v[k])) continue;
    ++filled;
    if (k < valid.front() && std::isfinite(wall_value)) {
      v[k] = wall_value;
      continue;
    }
    std::size_t best = valid.front();
    for (std::size_t q : valid)
      if (std::abs(static_cast<double>(q) - static_cast<double>(k)) <
          std::abs(static_cast<double>(best) - static_cast<double>(k)))
        best = q;
    v[k] = v[best];
  }
  return filled;
}

// Surface velocity of the tangential bin containing theta (bins are equal and cover 2 pi).
double surface_velocity_at(const DemFilmAverages& a, double theta) {
  std::size_t best = 0;
  double dmin = 1e300;
  for (std::size_t b = 0; b < a.bin_theta.size(); ++b) {
    const double d = std::abs(std::remainder(theta - a.bin_theta[b], 2.0 * M_PI));
    if (d < dmin) dmin = d, best = b;
  }
  return a.surface_velocity[best];
}

// Distinct axial levels (z/L) of the arcs, ascending.
std::vector<double> arc_levels(const DemFilmAverages& a) {
  std::vector<double> z = a.arc_z_over_length;
  std::sort(z.begin(), z.end());
  z.erase(std::unique(z.begin(), z.end(), [](double x, double y) { return std::abs(x - y) < 1e-9; }), z.end());
  return z;
}

// Linear interpolation weight of x between levels (held beyond the ends).
void bracket(const std::vector<double>& xs, double x, std::size_t& i, double& w) {
  if (xs.size() == 1 || x <= xs.front()) {
    i = 0, w = 0.0;
  } else if (x >= xs.back()) {
    i = xs.size() - 2, w = 1.0;
  } else {
    i = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
    w = (x - xs[i]) / (xs[i + 1] - xs[i]);
  }
}
}  // namespace

MappedFilm map_dem_film(const DemFilmAverages& a) {
  a.check();
  MappedFilm out;
  TangentialAverage& tg = out.tangential;
  const std::size_t nb = a.wall_distance_d.size();
  const double d = a.particle_diameter;

  // Zone shares and the surface-velocity factor of the tangential average.
  double moving = 0.0, mean_surface = 0.0, arc_surface = 0.0;
  for (std::size_t b = 0; b < a.bin_theta.size(); ++b) {
    moving += a.moving_zone_of_bin[b] ? 1.0 : 0.0;
    mean_surface += a.surface_velocity[b];
  }
  tg.moving_fraction = moving / a.bin_theta.size();
  mean_surface /= a.bin_theta.size();
  for (double th : a.arc_theta) arc_surface += surface_velocity_at(a, th);
  arc_surface /= a.arc_theta.size();
  if (!(arc_surface > 0.0) || !(mean_surface > 0.0))
    throw std::invalid_argument("film mapping: the surface axial velocity at the arc sections is not positive (" +
                                std::to_string(arc_surface) + " m/s): no moving film was sampled");
  tg.velocity_factor = mean_surface / arc_surface;

  // Arc profiles pooled per axial level (empty bins = NaN), then filled.
  const std::vector<double> levels = arc_levels(a);
  std::vector<std::vector<double>> u_level(levels.size(), std::vector<double>(nb)), u_sd = u_level;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    for (std::size_t k = 0; k < nb; ++k) {
      double s = 0.0, var = 0.0;
      int n = 0;
      for (std::size_t arc = 0; arc < a.arc_theta.size(); ++arc) {
        if (std::abs(a.arc_z_over_length[arc] - levels[l]) > 1e-9 || !(a.u_turns[arc][k] > 0.0)) continue;
        s += a.u_mean[arc][k];
        var += a.u_std[arc][k] * a.u_std[arc][k];
        ++n;
      }
      u_level[l][k] = n ? std::max(0.0, s / n) * tg.velocity_factor : kNaN;
      u_sd[l][k] = n ? std::sqrt(var / n) * tg.velocity_factor : kNaN;
    }
    tg.filled_bins += fill_empty(u_level[l], 0.0);
    fill_empty(u_sd[l], 0.0);
    tg.profile_z.push_back(levels[l] * a.length);
  }
  // Zone-weighted solid fraction; a bin with (almost) no particle volume counts as empty.
  std::vector<double> phi(nb), phi_sd(nb), D = a.dispersion, D_sd = a.dispersion_std;
  const double fm = tg.moving_fraction;
  // A zone the DEM never saw (the whole circumference moving, say) has NaN profiles: it
  // has no weight, so it takes the other zone's values rather than poisoning the sum.
  auto either = [](double x, double other) { return std::isfinite(x) ? x : other; };
  for (std::size_t k = 0; k < nb; ++k) {
    const double glued = a.phi_glued.empty() ? 0.0 : a.phi_glued[k];
    const double pm = either(a.phi_moving[k], a.phi_stationary[k]), ps = either(a.phi_stationary[k], pm);
    const double sm = either(a.phi_moving_std[k], a.phi_stationary_std[k]), ss = either(a.phi_stationary_std[k], sm);
    const double p = fm * pm + (1.0 - fm) * ps + glued;
    phi[k] = p > 1e-3 ? p : kNaN;
    phi_sd[k] = std::sqrt(fm * sm * sm + (1.0 - fm) * ss * ss);
    if (!std::isfinite(phi[k])) D[k] = D_sd[k] = kNaN;
  }
  tg.filled_bins += fill_empty(phi, kNaN);
  fill_empty(D, kNaN);
  fill_empty(D_sd, kNaN);
  for (double& x : phi) x = std::min(x, 0.74);  // the densest sphere packing
  const double w = a.bin_width_d() * d;
  for (const auto& u : u_level) {
    double flux = 0.0;
    for (std::size_t k = 0; k < nb; ++k)
      flux += 2.0 * M_PI * a.particle_density * phi[k] * u[k] * (a.drum_radius - a.wall_distance_d[k] * d) * w;
    tg.profile_flux_over_mdot.push_back(flux / a.mdot);
  }

  // Wall-distance points: the wall, the bin centres, and the thickest section's surface.
  thermal::FilmField& f = out.film;
  f.eta.push_back(0.0);
  for (double c : a.wall_distance_d) f.eta.push_back(c * d);
  const double t_max = *std::max_element(a.thickness.begin(), a.thickness.end());
  const bool extend = t_max > f.eta.back();
  if (extend) f.eta.push_back(t_max);
  auto row = [&](const std::vector<double>& bins, double wall) {
    std::vector<double> r{wall};
    r.insert(r.end(), bins.begin(), bins.end());
    if (extend) r.push_back(bins.back());
    return r;
  };
  f.z = a.section_z;
  f.t = a.thickness;
  const std::vector<double> phi_row = row(phi, phi[0]), phi_sd_row = row(phi_sd, phi_sd[0]);
  const std::vector<double> D_row = row(D, D[0]), D_sd_row = row(D_sd, D_sd[0]);
  for (double z : f.z) {
    std::size_t l;
    double w;
    bracket(tg.profile_z, z, l, w);
    const std::size_t l1 = levels.size() == 1 ? l : l + 1;
    std::vector<double> u(nb), us(nb);
    for (std::size_t k = 0; k < nb; ++k) {
      u[k] = (1.0 - w) * u_level[l][k] + w * u_level[l1][k];
      us[k] = (1.0 - w) * u_sd[l][k] + w * u_sd[l1][k];
    }
    const std::vector<double> ur = row(u, 0.0), usr = row(us, 0.0);
    f.u.insert(f.u.end(), ur.begin(), ur.end());
    f.u_std.insert(f.u_std.end(), usr.begin(), usr.end());
    f.phi.insert(f.phi.end(), phi_row.begin(), phi_row.end());
    f.phi_std.insert(f.phi_std.end(), phi_sd_row.begin(), phi_sd_row.end());
    f.D.insert(f.D.end(), D_row.begin(), D_row.end());
    f.D_std.insert(f.D_std.end(), D_sd_row.begin(), D_sd_row.end());
  }
  f.drum_diameter = 2.0 * a.drum_radius;
  f.length = a.length;
  f.omega = a.omega;
  f.mdot = a.mdot;
  f.particle_diameter = d;
  f.scaling = "none: the DEM drum itself";
  f.check();
  return out;
}

}  // namespace centrec::coupling
