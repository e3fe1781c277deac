#include "io/dem_output_h5.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/atomic_write.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

namespace {

using dem::scene::SampledFilm;
using dem::scene::MassFlowSample;

// The schema of /mass_flow and /film: each dataset once, with its unit, its dimension scale
// and how it is taken from the run and read back into it. A row without `set` is an output
// only (a cached run's coupling does not use it).

// /mass_flow: one column per sample record field, over /mass_flow/time.
struct FlowColumn {
  const char* name;
  const char* units;
  double (*get)(const MassFlowSample&);
  void (*set)(MassFlowSample&, double);
};
const FlowColumn kFlowColumns[] = {
    {"time", "s", [](const MassFlowSample& s) { return s.time; }, [](MassFlowSample& s, double v) { s.time = v; }},
    {"fed", "kg", [](const MassFlowSample& s) { return s.fed; }, [](MassFlowSample& s, double v) { s.fed = v; }},
    {"out", "kg", [](const MassFlowSample& s) { return s.out; }, [](MassFlowSample& s, double v) { s.out = v; }},
    {"lost", "kg", [](const MassFlowSample& s) { return s.lost; }, [](MassFlowSample& s, double v) { s.lost = v; }},
    {"holdup", "kg", [](const MassFlowSample& s) { return s.holdup; },
     [](MassFlowSample& s, double v) { s.holdup = v; }},
    {"particles", "1", [](const MassFlowSample& s) { return static_cast<double>(s.particles); },
     [](MassFlowSample& s, double v) { s.particles = static_cast<std::int64_t>(v); }},
    {"slice_axial_flow", "kg/s", [](const MassFlowSample& s) { return s.axial_flow; },
     [](MassFlowSample& s, double v) { s.axial_flow = v; }},
};

// One field of a vector of records, as a dataset column.
template <class T>
std::vector<double> each(const std::vector<T>& v, double T::*m) {
  std::vector<double> x;
  for (const T& e : v) x.push_back(e.*m);
  return x;
}
// The column `x` into a vector of records: sized by the first column read, the others must match.
template <class T>
void fill(std::vector<T>& v, const std::vector<double>& x, double T::*m) {
  if (v.empty()) v.resize(x.size());
  if (v.size() != x.size()) throw std::runtime_error("differs in length from the other columns of its records");
  for (std::size_t k = 0; k < x.size(); ++k) v[k].*m = x[k];
}

// /film 1D datasets; `scale` is the /film dataset of their axis ("" = none).
struct FilmColumn {
  const char* name;
  const char* units;
  const char* scale;
  const char* scale_label;
  std::vector<double> (*get)(const SampledFilm&);
  void (*set)(SampledFilm&, const std::vector<double>&);
};
const FilmColumn kFilmColumns[] = {
    {"section_z", "m", "", "", [](const SampledFilm& f) { return f.section_z; },
     [](SampledFilm& f, const std::vector<double>& x) { f.section_z = x; }},
    {"thickness_mean", "m", "section_z", "z",
     [](const SampledFilm& f) { return each(f.section_thickness, &film::LengthStat::mean_m); },
     [](SampledFilm& f, const std::vector<double>& x) { fill(f.section_thickness, x, &film::LengthStat::mean_m); }},
    {"thickness_std", "m", "section_z", "z",
     [](const SampledFilm& f) { return each(f.section_thickness, &film::LengthStat::std_m); },
     [](SampledFilm& f, const std::vector<double>& x) { fill(f.section_thickness, x, &film::LengthStat::std_m); }},
    {"bin_theta", "rad", "", "", [](const SampledFilm& f) { return f.bin_theta; },
     [](SampledFilm& f, const std::vector<double>& x) { f.bin_theta = x; }},
    {"surface_axial_velocity", "m/s", "bin_theta", "theta", [](const SampledFilm& f) { return f.surface_velocity; },
     [](SampledFilm& f, const std::vector<double>& x) { f.surface_velocity = x; }},
    {"moving_zone_of_bin", "1", "bin_theta", "theta",
     [](const SampledFilm& f) { return std::vector<double>(f.zones.zone_of_bin.begin(), f.zones.zone_of_bin.end()); },
     [](SampledFilm& f, const std::vector<double>& x) {
       f.zones.zone_of_bin.clear();
       for (double z : x) f.zones.zone_of_bin.push_back(z > 0.5 ? 1 : 0);
     }},
    {"arc_theta", "rad", "", "", [](const SampledFilm& f) { return each(f.arcs, &film::ArcSection::theta); }, nullptr},
    {"arc_z_over_length", "1", "", "",
     [](const SampledFilm& f) { return each(f.arcs, &film::ArcSection::z_over_length); }, nullptr},
    {"wall_distance_d", "d", "", "", [](const SampledFilm& f) { return f.bin_centre_d; },
     [](SampledFilm& f, const std::vector<double>& x) { f.bin_centre_d = x; }},
    {"dispersion", "m2/s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::coefficient); },
     [](SampledFilm& f, const std::vector<double>& x) { fill(f.dispersion, x, &film::DispersionBin::coefficient); }},
    {"dispersion_std", "m2/s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::coefficient_std); },
     [](SampledFilm& f, const std::vector<double>& x) { fill(f.dispersion, x, &film::DispersionBin::coefficient_std); }},
    {"dispersion_drift", "m/s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::drift); }, nullptr},
    {"dispersion_fit_lag_min", "s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::fit_lag_min); }, nullptr},
    {"dispersion_fit_lag_max", "s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::fit_lag_max); }, nullptr},
    {"dispersion_crossing_time", "s", "wall_distance_d", "wall distance",
     [](const SampledFilm& f) { return each(f.dispersion, &film::DispersionBin::crossing_time); }, nullptr},
    {"dispersion_lags", "s", "", "", [](const SampledFilm& f) { return f.dispersion_lags; }, nullptr},
    {"ring_z", "m", "", "", [](const SampledFilm& f) { return f.ring_z; },
     [](SampledFilm& f, const std::vector<double>& x) { f.ring_z = x; }},
};

// /film profiles [rows][wall-distance bins] as <name>_mean, _std (units) and _turns (the
// periods per bin), over /film/wall_distance_d; rows over the row scales given.
struct FilmProfile {
  const char* name;
  const char* units;
  std::vector<std::vector<film::ProfileBin>> SampledFilm::*member;
  const char* row_scales[2][2];  // {dataset, label}, up to two ("" = none)
  bool read;
};
const FilmProfile kFilmProfiles[] = {
    {"axial_velocity", "m/s", &SampledFilm::velocity_profiles, {{"arc_theta", "arc theta"}, {"arc_z_over_length", "arc z/L"}}, false},
    {"solid_fraction", "1", &SampledFilm::solid_fraction, {{"", ""}, {"", ""}}, false},
    {"ring_solid_fraction", "1", &SampledFilm::ring_solid_fraction, {{"ring_z", "z"}, {"", ""}}, true},
    {"ring_volume_flux", "m/s", &SampledFilm::ring_volume_flux, {{"ring_z", "z"}, {"", ""}}, true},
};

// /film number attributes.
struct FilmNumber {
  const char* name;
  double (*get)(const SampledFilm&);
  void (*set)(SampledFilm&, double);
};
const FilmNumber kFilmNumbers[] = {
    {"sampled_turns", [](const SampledFilm& f) { return static_cast<double>(f.turns); },
     [](SampledFilm& f, double v) { f.turns = static_cast<std::size_t>(v); }},
    {"snapshots", [](const SampledFilm& f) { return static_cast<double>(f.snapshots); },
     [](SampledFilm& f, double v) { f.snapshots = static_cast<std::size_t>(v); }},
    {"mean_thickness_m", [](const SampledFilm& f) { return f.mean_thickness.mean_m; }, nullptr},
    {"mean_thickness_std_m", [](const SampledFilm& f) { return f.mean_thickness.std_m; }, nullptr},
};

const char* const kProfileParts[] = {"_mean", "_std", "_turns"};

void write_mass_flow(H5File& f, const std::vector<MassFlowSample>& log) {
  f.create_group("/mass_flow");
  for (const FlowColumn& c : kFlowColumns) {
    std::vector<double> x;
    for (const MassFlowSample& s : log) x.push_back(c.get(s));
    f.write(std::string("/mass_flow/") + c.name, x, c.units);
  }
  f.set_attribute("/mass_flow", "description",
                  "cumulative since t = 0: fed, out (through the outlet), lost (escaped elsewhere); holdup and "
                  "particles: free particles in the drum; rates are differences over time");
  for (const FlowColumn& c : kFlowColumns)
    if (std::string(c.name) != "time") f.attach_scale(std::string("/mass_flow/") + c.name, 0, "/mass_flow/time", "time");
}

// [rows][bins] profile bins -> mean, std and period-count matrices.
void write_profile(H5File& f, const FilmProfile& p, const std::vector<std::vector<film::ProfileBin>>& rows) {
  if (rows.empty()) return;
  const std::string path = std::string("/film/") + p.name;
  const std::size_t n = rows.size(), cols = rows[0].size();
  std::vector<double> mean, sd, periods;
  for (const auto& row : rows)
    for (const auto& b : row) {
      mean.push_back(b.mean);
      sd.push_back(b.stddev);
      periods.push_back(static_cast<double>(b.periods));
    }
  f.write(path + "_mean", mean, {n, cols}, p.units);
  f.write(path + "_std", sd, {n, cols}, p.units);
  f.write(path + "_turns", periods, {n, cols}, "1");
}

void write_film(H5File& f, const SampledFilm& ff) {
  if (ff.snapshots == 0) return;
  f.create_group("/film");
  for (const FilmNumber& a : kFilmNumbers) f.set_attribute("/film", a.name, a.get(ff));
  f.set_attribute("/film", "theta_convention",
                  "theta increases against the drum rotation; 90 deg = top (opposite gravity's transverse part)");
  for (const FilmColumn& c : kFilmColumns) f.write(std::string("/film/") + c.name, c.get(ff), c.units);
  for (const FilmProfile& p : kFilmProfiles) write_profile(f, p, ff.*p.member);
  f.set_attribute("/film/solid_fraction_mean", "rows", "0 = stationary zone, 1 = moving zone");
  // Dispersion: D from the slope of the MSD (docs/film_sampling.md "Wall-normal dispersion"),
  // with the lags and the axial window it used.
  std::vector<double> msd, msd_n;
  for (const auto& b : ff.dispersion) {
    msd.insert(msd.end(), b.msd.begin(), b.msd.end());
    for (std::size_t n : b.msd_samples) msd_n.push_back(static_cast<double>(n));
  }
  const std::size_t nlag = ff.dispersion_lags.size();
  const bool with_msd = !ff.dispersion.empty() && nlag > 0 && msd.size() == ff.dispersion.size() * nlag;
  if (with_msd) {
    f.write("/film/dispersion_msd", msd, {ff.dispersion.size(), nlag}, "m2");
    f.write("/film/dispersion_msd_samples", msd_n, {ff.dispersion.size(), nlag}, "1");
  }
  f.set_attribute("/film/dispersion", "method",
                  "wall-normal self-diffusion: half the slope of MSD(lag) = 2 D lag + c (variance of the radial "
                  "displacement, drift removed) by starting wall-distance bin, fitted over the lags from "
                  "dispersion_fit_lag_min to dispersion_fit_lag_max (<= crossing_fraction x the bin-crossing time "
                  "w^2/(2D), at least two lags); std = spread over turns of the per-turn fits");
  f.set_attribute("/film/dispersion", "z_min_m", ff.dispersion_z_min);
  f.set_attribute("/film/dispersion", "z_max_m", ff.dispersion_z_max);
  f.set_attribute("/film/dispersion", "crossing_fraction", ff.dispersion_crossing_fraction);
  f.set_attribute("/film/dispersion_lags", "series",
                  "the fine series (position samples inside each snapshot interval, dem.sampling.dispersion_spacing "
                  "apart) then the coarse series (the snapshots, within a turn); 0 = a series without data");
  f.set_attribute("/film/ring_volume_flux_mean", "meaning",
                  "phi * u over the whole circumference per axial section (rows) and wall-distance bin; "
                  "axial mass flow of a section = rho_s * sum over bins of this * shell area");
  // The dimension scales.
  for (const FilmColumn& c : kFilmColumns)
    if (*c.scale) f.attach_scale(std::string("/film/") + c.name, 0, std::string("/film/") + c.scale, c.scale_label);
  for (const FilmProfile& p : kFilmProfiles) {
    if ((ff.*p.member).empty()) continue;
    for (const char* part : kProfileParts) {
      const std::string path = std::string("/film/") + p.name + part;
      for (const auto& rs : p.row_scales)
        if (*rs[0]) f.attach_scale(path, 0, std::string("/film/") + rs[0], rs[1]);
      f.attach_scale(path, 1, "/film/wall_distance_d", "wall distance");
    }
  }
  if (with_msd)
    for (const char* name : {"dispersion_msd", "dispersion_msd_samples"}) {
      f.attach_scale(std::string("/film/") + name, 0, "/film/wall_distance_d", "wall distance");
      f.attach_scale(std::string("/film/") + name, 1, "/film/dispersion_lags", "lag");
    }
}

// [rows][bins] profile bins from the _mean, _std and _turns datasets of a profile.
std::vector<std::vector<film::ProfileBin>> read_profile(const H5File& f, const std::string& path) {
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

// One snapshot: the free particles, then the glued layer (glued = 1).
void write_snapshot(H5File& f, const NamedSnapshot& s) {
  const std::string g = "/snapshots/" + s.name;
  f.create_group(g);
  std::vector<double> pos, vel, radius;
  std::vector<std::int64_t> id, vertex;
  std::vector<std::int8_t> glued;
  for (const auto* part : {&s.data, &s.glued}) {
    const auto& d = *part;
    for (std::size_t i = 0; i < d.size(); ++i) {
      pos.insert(pos.end(), {d.x[i], d.y[i], d.z[i]});
      vel.insert(vel.end(), {d.vx[i], d.vy[i], d.vz[i]});
      radius.push_back(d.radius[i]);
      id.push_back(d.id[i]);
      glued.push_back(part == &s.glued ? 1 : 0);
      vertex.push_back(static_cast<std::int64_t>(vertex.size()));
    }
  }
  const std::size_t n = radius.size();
  f.write(g + "/position", pos, {n, 3}, "m");
  f.write(g + "/velocity", vel, {n, 3}, "m/s");
  f.write(g + "/radius", radius, "m");
  f.write_int64(g + "/id", id, {n}, "1");
  f.write_int8(g + "/glued", glued, "1");
  f.write_int64(g + "/vertex", vertex, {n}, "1");
  f.set_attribute(g, "time", s.data.time);
  f.set_attribute(g, "free_particles", static_cast<double>(s.data.size()));
  f.set_attribute(g, "glued_particles", static_cast<double>(s.glued.size()));
}

std::string data_item(const std::string& dims, const char* type, int precision, const std::string& path) {
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"" + std::to_string(precision) +
         "\" Format=\"HDF\">dem.h5:" + path + "</DataItem>";
}

// The drum's inner surface as triangles in the scene frame (axis on z from 0 to L): the
// cylinder, the back plate and the outlet lip, enough to see the drum in ParaView. Returns
// its XDMF (drum.xmf).
std::string write_drum(H5File& f, const dem::scene::SceneConfig& c) {
  const int seg = 72;
  const double R = 0.5 * c.drum.diameter, L = c.slice.enabled ? c.slice.length : c.drum.length;
  const double pi = 3.14159265358979323846;
  std::vector<double> pts;
  std::vector<std::int64_t> tri;
  auto ring = [&](double r, double z) {
    const auto first = static_cast<std::int64_t>(pts.size() / 3);
    for (int k = 0; k < seg; ++k) pts.insert(pts.end(), {r * std::cos(2 * pi * k / seg), r * std::sin(2 * pi * k / seg), z});
    return first;
  };
  auto band = [&](std::int64_t a, std::int64_t b) {  // quads between two rings, as triangles
    for (int k = 0; k < seg; ++k) {
      const int k1 = (k + 1) % seg;
      tri.insert(tri.end(), {a + k, a + k1, b + k, b + k, a + k1, b + k1});
    }
  };
  band(ring(R, 0.0), ring(R, L));
  if (!c.slice.enabled && c.drum.back_plate) band(ring(R, 0.0), ring(0.0, 0.0));
  if (!c.slice.enabled && c.drum.lip_height > 0.0) band(ring(R, L), ring(R - c.drum.lip_height, L));
  f.write("/drum/points", pts, {pts.size() / 3, 3}, "m");
  f.write_int64("/drum/triangles", tri, {tri.size() / 3, 3}, "1");
  f.set_attribute("/drum", "frame", "drum axis on z from 0 to L; the drum turns about it (the glued layer with it)");
  const std::string np = std::to_string(pts.size() / 3), nt = std::to_string(tri.size() / 3);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n  <Grid Name=\"drum\" GridType=\"Uniform\">\n"
    << "   <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << nt << "\">"
    << data_item(nt + " 3", "Int", 8, "/drum/triangles") << "</Topology>\n"
    << "   <Geometry GeometryType=\"XYZ\">" << data_item(np + " 3", "Float", 8, "/drum/points") << "</Geometry>\n"
    << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x.str();
}

// The particle snapshots as an XDMF 3 temporal collection over dem.h5 (ParaView, meshio).
std::string particles_xdmf(const std::vector<NamedSnapshot>& snaps) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& s : snaps) {
    const std::string n = std::to_string(s.data.size() + s.glued.size());
    const std::string g = "/snapshots/" + s.name;
    auto attribute = [&](const char* name, const char* kind, const std::string& dims, const char* type, int precision) {
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"Node\">"
        << data_item(dims, type, precision, g + "/" + name) << "</Attribute>\n";
    };
    x << "   <Grid Name=\"" << s.name << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << s.data.time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">"
      << data_item(n, "Int", 8, g + "/vertex") << "</Topology>\n"
      << "    <Geometry GeometryType=\"XYZ\">" << data_item(n + " 3", "Float", 8, g + "/position") << "</Geometry>\n";
    attribute("velocity", "Vector", n + " 3", "Float", 8);
    attribute("radius", "Scalar", n, "Float", 8);
    attribute("id", "Scalar", n, "Int", 8);
    attribute("glued", "Scalar", n, "Int", 1);
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace

std::vector<dem::scene::MassFlowSample> read_mass_flow_log(const H5File& f) {
  std::vector<MassFlowSample> log;
  for (const FlowColumn& c : kFlowColumns) {
    const std::vector<double> x = f.read(std::string("/mass_flow/") + c.name);
    if (log.empty()) log.resize(x.size());
    if (x.size() != log.size()) throw std::runtime_error(std::string("/mass_flow/") + c.name + " differs in length from time");
    for (std::size_t k = 0; k < x.size(); ++k) c.set(log[k], x[k]);
  }
  return log;
}

dem::scene::SampledFilm read_film_fields(const H5File& f) {
  SampledFilm ff;
  for (const FilmNumber& a : kFilmNumbers)
    if (a.set) a.set(ff, f.number_attribute("/film", a.name));
  for (const FilmColumn& c : kFilmColumns)
    if (c.set) {
      const std::string path = std::string("/film/") + c.name;
      const std::vector<double> x = f.read(path);
      try {
        c.set(ff, x);
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(path + ": " + e.what());
      }
    }
  for (const FilmProfile& p : kFilmProfiles)
    if (p.read) ff.*p.member = read_profile(f, std::string("/film/") + p.name);
  return ff;
}

void write_dem_h5(const std::string& dir, const Provenance& provenance, const dem::scene::SceneConfig& scene,
                  const DemRunResult& run) {
  H5File f = H5File::create(dir + "/dem.h5");
  write_provenance(f, provenance);
  f.set_attribute("/", "engine", run.engine);
  f.set_attribute("/", "engine_version", run.engine_version);
  f.set_attribute("/", "drum_radius_m", 0.5 * scene.drum.diameter);
  f.set_attribute("/", "particle_diameter_m", scene.particle.diameter);
  f.set_attribute("/", "turn_period_s", dem::scene::turn_period(scene));
  write_mass_flow(f, run.mass_flow);
  write_film(f, run.fields);
  f.create_group("/snapshots");
  f.set_attribute("/snapshots", "snapshot_stride", static_cast<double>(run.snapshot_stride));
  for (const auto& s : run.snapshots) write_snapshot(f, s);
  const std::string drum = write_drum(f, scene);
  f.commit();
  write_text_atomically(dir + "/dem.xmf", particles_xdmf(run.snapshots));
  write_text_atomically(dir + "/drum.xmf", drum);
}

}  // namespace centrec::io
