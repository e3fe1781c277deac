#include "coupling/film_along_drum.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "coupling/film_mapping.hpp"

namespace centrec::coupling {

std::vector<std::size_t> sections_past_feeder(const DemFilmAverages& a) {
  if (a.slice || a.ring_z.size() < 2)
    throw std::invalid_argument(
        "film mapping along_drum: the DEM is a periodic slice (one axial section); a slice's film is as_measured");
  const double half = 0.5 * (a.ring_z[1] - a.ring_z[0]);  // sections of equal length
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < a.ring_z.size(); ++i)
    if (a.ring_z[i] - half >= a.feed_end * (1.0 - 1e-12)) out.push_back(i);
  if (out.empty())
    throw std::invalid_argument("film mapping along_drum: no axial section lies past the feeder region (it ends at " +
                                std::to_string(a.feed_end) + " m of the drum's " + std::to_string(a.length) + " m)");
  return out;
}

namespace {
FilmMappingResult along_drum(const DemFilmAverages& a, FilmTop top_at) {
  a.check();
  const std::vector<std::size_t> sections = sections_past_feeder(a);
  MappedFilm m = map_dem_sections(a, sections, kFilmSolidFractionCut, top_at);
  FilmMappingResult r{std::move(m.film), {}};
  FilmMappingReport& rep = r.report;
  const bool by_flow = top_at == FilmTop::carried_flow;
  rep.mapping = by_flow ? "along_drum_carried_flow" : "along_drum";
  rep.figures = {
      {by_flow ? "film_carried_flow_share" : "film_solid_fraction_cut", by_flow ? kCarriedFlowShare : m.cut.phi_cut},
      {"first_section_z_m", a.ring_z[sections.front()]}};
  rep.profiles = {{"film_thickness", "m", m.cut.thickness, "", ""},
                  {"flow_within_film_share", "1", m.cut.flow_within_share, "flow_within_film_share_min", ""}};
  const auto [lo, hi] = std::minmax_element(m.cut.flow_within_share.begin(), m.cut.flow_within_share.end());
  const auto [t_lo, t_hi] = std::minmax_element(m.cut.thickness.begin(), m.cut.thickness.end());
  char top[80];
  if (by_flow)
    std::snprintf(top, sizeof top, "where it carries %.1f %% of the section's flow", 100.0 * kCarriedFlowShare);
  else
    std::snprintf(top, sizeof top, "where phi crosses %.2g", m.cut.phi_cut);
  char b[260];
  std::snprintf(b, sizeof b,
                "along the drum from z = %.3g m (%zu sections past the feeder), %.2f-%.2f d thick %s (%.1f-%.1f %% of "
                "the DEM's flow inside)",
                a.ring_z[sections.front()], sections.size(), *t_lo / a.particle_diameter, *t_hi / a.particle_diameter,
                top, 100.0 * *lo, 100.0 * *hi);
  rep.text = b;
  return r;
}
}  // namespace

FilmMappingResult map_film_along_drum(const DemFilmAverages& a) { return along_drum(a, FilmTop::at_crossing); }

FilmMappingResult map_film_along_drum_carried_flow(const DemFilmAverages& a) {
  return along_drum(a, FilmTop::carried_flow);
}

}  // namespace centrec::coupling
