#include "film_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace centrec::coupling {

namespace {
// Empty bins (NaN) take the nearest sampled bin's value.
void fill_empty(std::vector<double>& v) {
  std::vector<std::size_t> valid;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::isfinite(v[k])) valid.push_back(k);
  if (valid.empty()) throw std::invalid_argument("film mapping: a DEM profile has no sampled bin at all");
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (std::isfinite(v[k])) continue;
    std::size_t best = valid.front();
    for (std::size_t q : valid)
      if (std::abs(static_cast<double>(q) - static_cast<double>(k)) <
          std::abs(static_cast<double>(best) - static_cast<double>(k)))
        best = q;
    v[k] = v[best];
  }
}
}  // namespace

MappedFilm map_dem_film(const DemFilmAverages& a, double phi_cut, FilmTop top_at) {
  a.check();
  // A drum's sections next to the feeder and the outlet hold the small drum's own inflow
  // and outflow (particles falling in from the feeder, the film leaving over the edge),
  // not the developed film: the thermal film takes the sections of z/L 0.2-0.8, held
  // toward the ends, as the solid-fraction sampler's window does.
  std::vector<std::size_t> sections;
  for (std::size_t i = 0; i < a.ring_z.size(); ++i) {
    const double zl = a.ring_z[i] / a.length;
    if (a.ring_z.size() > 1 && (zl < kDevelopedFrom || zl > kDevelopedTo)) continue;
    sections.push_back(i);
  }
  return map_dem_sections(a, sections, phi_cut, top_at);
}

MappedFilm map_dem_sections(const DemFilmAverages& a, const std::vector<std::size_t>& sections, double phi_cut,
                            FilmTop top_at) {
  a.check();
  if (!(phi_cut > 0.0 && phi_cut < 0.74)) throw std::invalid_argument("film mapping: phi_cut must be in (0, 0.74)");
  if (sections.empty()) throw std::invalid_argument("film mapping: no axial section selected");
  MappedFilm out;
  out.cut.phi_cut = phi_cut;
  const std::size_t nb = a.wall_distance_d.size();
  const double d = a.particle_diameter, w = a.bin_width_d() * d, R = a.drum_radius;

  // Dispersion: one profile for the whole film, measured by the DEM over its developed film
  // (docs/film_sampling.md "Wall-normal dispersion"); bins where it was not measured take
  // the nearest measured bin's value.
  std::vector<double> D = a.dispersion, D_sd = a.dispersion_std;
  for (std::size_t k = 0; k < nb; ++k)
    if (!(D[k] >= 0.0)) D[k] = D_sd[k] = NAN;
  fill_empty(D);
  fill_empty(D_sd);

  // Wall-distance points: the wall, the bin centres with kPointsPerGap - 1 points between
  // neighbours, the top of the last bin. Between centres phi and the flux phi u are linear
  // and u = flux / phi: the film then carries its bins' flow (phi and u each linear over a
  // whole gap would carry the product of two lines, 3 % more than a slice's bins and 8-10 %
  // more than a fed drum's, docs/coupling.md "Film as measured").
  thermal::FilmField& f = out.film;
  f.eta.push_back(0.0);
  for (std::size_t k = 0; k < nb; ++k) {
    for (int j = 1; k > 0 && j < kPointsPerGap; ++j)
      f.eta.push_back((a.wall_distance_d[k - 1] + static_cast<double>(j) / kPointsPerGap * a.bin_width_d()) * d);
    f.eta.push_back(a.wall_distance_d[k] * d);
  }
  f.eta.push_back(static_cast<double>(nb) * w);
  // The bins' values at the points: `bins` linear between centres, or (weights given) the
  // product weights x bins linear and divided by the linear weights (u from the flux).
  auto append = [](std::vector<double>& to, const std::vector<double>& bins, double wall,
                   const std::vector<double>* weights = nullptr) {
    to.push_back(wall);
    for (std::size_t k = 0; k < bins.size(); ++k) {
      for (int j = 1; k > 0 && j < kPointsPerGap; ++j) {
        const double s = static_cast<double>(j) / kPointsPerGap;
        if (!weights) {
          to.push_back((1.0 - s) * bins[k - 1] + s * bins[k]);
        } else {
          const std::vector<double>& p = *weights;
          const double pw = (1.0 - s) * p[k - 1] + s * p[k];
          to.push_back(pw > 0.0 ? ((1.0 - s) * p[k - 1] * bins[k - 1] + s * p[k] * bins[k]) / pw : 0.0);
        }
      }
      to.push_back(bins[k]);
    }
    to.push_back(bins.back());
  };

  for (const std::size_t i : sections) {
    f.z.push_back(a.ring_z[i]);
    std::vector<double> phi(nb), phi_sd(nb), u(nb), u_sd(nb);
    for (std::size_t k = 0; k < nb; ++k) {
      const double glued = a.phi_glued.empty() ? 0.0 : a.phi_glued[k];
      const double p = a.ring_phi[i][k] + glued;
      phi[k] = std::min(p, 0.74);  // the densest sphere packing
      phi_sd[k] = a.ring_phi_std[i][k];
      // Mass-weighted velocity of everything in the bin (glued spheres at rest included).
      // A bin at rest can average a slightly negative speed (particles jostling back and
      // forth); the thermal film flows toward the outlet only, so it is taken as at rest (the
      // flux closure counts what that leaves out).
      u[k] = p > 0.0 ? std::max(0.0, a.ring_flux[i][k] / p) : 0.0;
      u_sd[k] = p > 0.0 ? a.ring_flux_std[i][k] / p : 0.0;
    }
    // Each bin's share of the section's flow (cylindrical: u phi (R - eta)).
    std::vector<double> flow(nb);
    double all = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      flow[k] = a.ring_flux[i][k] * (R - a.wall_distance_d[k] * d);
      all += flow[k];
    }
    double t = 0.0;
    std::size_t held_from = 0;  // the points from here up hold the film's top values
    if (top_at == FilmTop::carried_flow) {
      // The top where the flow counted from the wall, uniform within a bin, reaches the
      // share; the bin it lies in is kept as measured.
      if (!(all > 0.0))
        throw std::invalid_argument("film mapping: no flow at z = " + std::to_string(a.ring_z[i]) + " m");
      const double target = kCarriedFlowShare * all;
      double below = 0.0;
      std::size_t k = 0;
      while (k + 1 < nb && below + std::max(0.0, flow[k]) < target) below += std::max(0.0, flow[k++]);
      t = (static_cast<double>(k) + std::clamp((target - below) / std::max(flow[k], 1e-300), 0.0, 1.0)) * w;
      held_from = k + 1;
      // The film is continuous from the wall: an empty bin below that top ends it at the
      // bin's lower edge (the flow above the gap is left out; the flux closure counts it). A
      // void inside the film would hold neither heat nor flow.
      std::size_t gap = 0;
      while (gap < nb && phi[gap] > 0.0) ++gap;
      if (gap == 0)
        throw std::invalid_argument("film mapping: no film at z = " + std::to_string(a.ring_z[i]) +
                                    " m (the first bin is empty)");
      if (gap <= k) {
        t = static_cast<double>(gap) * w;
        held_from = gap;
      }
    } else {
      // The film: bins from the wall up with phi >= phi_cut, without a gap.
      std::size_t top = 0;
      while (top < nb && phi[top] >= phi_cut) ++top;
      if (top == 0)
        throw std::invalid_argument("film mapping: no film at z = " + std::to_string(a.ring_z[i]) +
                                    " m (solid fraction of the first bin " + std::to_string(phi[0]) + " < " +
                                    std::to_string(phi_cut) + ")");
      t = static_cast<double>(top) * w;
      held_from = top;
      // The first bin below the cut is kept as measured when the film ends where the
      // profile, linear between bin centres, crosses phi_cut.
      if (top_at == FilmTop::at_crossing && top < nb) {
        t = (a.wall_distance_d[top - 1] * d) +
            (phi[top - 1] - phi_cut) / (phi[top - 1] - phi[top]) * w;  // phi[top - 1] >= cut > phi[top]
        held_from = top + 1;
      }
    }
    double within = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      if (top_at == FilmTop::whole_bins)
        within += k < held_from ? flow[k] : 0.0;
      else  // the part of bin k (k w to (k + 1) w from the wall) below the film's top
        within += flow[k] * std::clamp((t - static_cast<double>(k) * w) / w, 0.0, 1.0);
    }
    // Above the film the thermal model reads nothing (FilmField ignores eta > t); the points
    // there hold the film's top values so the field stays a valid film everywhere.
    for (std::size_t k = held_from; k < nb; ++k) {
      phi[k] = phi[held_from - 1], phi_sd[k] = phi_sd[held_from - 1];
      u[k] = u[held_from - 1], u_sd[k] = u_sd[held_from - 1];
    }
    out.cut.thickness.push_back(t);
    out.cut.flow_within_share.push_back(all > 0.0 ? within / all : 0.0);
    f.t.push_back(t);
    append(f.phi, phi, phi[0]);
    append(f.phi_std, phi_sd, phi_sd[0]);
    append(f.u, u, 0.0, &phi);  // at rest on the wall
    append(f.u_std, u_sd, 0.0, &phi);
    append(f.D, D, D[0]);
    append(f.D_std, D_sd, D_sd[0]);
  }
  f.drum_diameter = 2.0 * R;
  f.length = a.length;
  f.omega = a.omega;
  f.mdot = a.mdot;
  f.particle_diameter = d;
  f.scaling = "none: the DEM drum itself";
  f.check();
  return out;
}

FilmMappingResult map_film_as_measured_carried_flow(const DemFilmAverages& a) {
  MappedFilm m = map_dem_film(a, kFilmSolidFractionCut, FilmTop::carried_flow);
  FilmMappingResult r{std::move(m.film), {}};
  FilmMappingReport& rep = r.report;
  rep.mapping = "as_measured_carried_flow";
  rep.figures = {{"film_carried_flow_share", kCarriedFlowShare}};
  rep.profiles = {{"film_thickness", "m", m.cut.thickness, "", ""},
                  {"flow_within_film_share", "1", m.cut.flow_within_share, "flow_within_film_share_min", ""}};
  char b[160];
  std::snprintf(b, sizeof b, "up to where it carries %.1f %% of the DEM's flow", 100.0 * kCarriedFlowShare);
  rep.text = b;
  return r;
}

FilmMappingResult map_film_as_measured(const DemFilmAverages& a) {
  MappedFilm m = map_dem_film(a);
  FilmMappingResult r{std::move(m.film), {}};
  FilmMappingReport& rep = r.report;
  rep.mapping = "as_measured";
  rep.figures = {{"film_solid_fraction_cut", m.cut.phi_cut}};
  rep.profiles = {{"film_thickness", "m", m.cut.thickness, "", ""},
                  {"flow_within_film_share", "1", m.cut.flow_within_share, "flow_within_film_share_min", ""}};
  const auto [lo, hi] = std::minmax_element(m.cut.flow_within_share.begin(), m.cut.flow_within_share.end());
  char b[160];
  std::snprintf(b, sizeof b, "where phi >= %.2g (%.1f-%.1f %% of the DEM's flow inside)", m.cut.phi_cut, 100.0 * *lo,
                100.0 * *hi);
  rep.text = b;
  return r;
}

}  // namespace centrec::coupling
