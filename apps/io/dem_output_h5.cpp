#include "io/dem_output_h5.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/atomic_write.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

namespace {

void write_mass_flow(H5File& f, const std::vector<dem::scene::MassFlowSample>& log) {
  f.create_group("/mass_flow");
  std::vector<double> t, fed, out, lost, hold, n, axial;
  for (const auto& s : log) {
    axial.push_back(s.axial_flow);
    t.push_back(s.time);
    fed.push_back(s.fed);
    out.push_back(s.out);
    lost.push_back(s.lost);
    hold.push_back(s.holdup);
    n.push_back(static_cast<double>(s.particles));
  }
  f.write("/mass_flow/time", t, "s");
  f.write("/mass_flow/fed", fed, "kg");
  f.write("/mass_flow/out", out, "kg");
  f.write("/mass_flow/lost", lost, "kg");
  f.write("/mass_flow/holdup", hold, "kg");
  f.write("/mass_flow/particles", n, "1");
  f.write("/mass_flow/slice_axial_flow", axial, "kg/s");
  f.set_attribute("/mass_flow", "description",
                  "cumulative since t = 0: fed, out (through the outlet), lost (escaped elsewhere); holdup and "
                  "particles: free particles in the drum; rates are differences over time");
  for (const char* name : {"fed", "out", "lost", "holdup", "particles", "slice_axial_flow"})
    f.attach_scale(std::string("/mass_flow/") + name, 0, "/mass_flow/time", "time");
}

// [rows][bins] profile bins -> mean, std and period-count matrices.
void write_profiles(H5File& f, const std::string& path, const std::vector<std::vector<film::ProfileBin>>& p,
                    const std::string& units) {
  if (p.empty()) return;
  const std::size_t rows = p.size(), cols = p[0].size();
  std::vector<double> mean, sd, periods;
  for (const auto& row : p)
    for (const auto& b : row) {
      mean.push_back(b.mean);
      sd.push_back(b.stddev);
      periods.push_back(static_cast<double>(b.periods));
    }
  f.write(path + "_mean", mean, {rows, cols}, units);
  f.write(path + "_std", sd, {rows, cols}, units);
  f.write(path + "_turns", periods, {rows, cols}, "1");
  for (const char* part : {"_mean", "_std", "_turns"}) f.attach_scale(path + part, 1, "/film/wall_distance_d", "wall distance");
}

void write_film(H5File& f, const dem::scene::FilmFields& ff) {
  if (ff.snapshots == 0) return;
  f.create_group("/film");
  f.set_attribute("/film", "sampled_turns", static_cast<double>(ff.turns));
  f.set_attribute("/film", "snapshots", static_cast<double>(ff.snapshots));
  f.set_attribute("/film", "theta_convention",
                  "theta increases against the drum rotation; 90 deg = top (opposite gravity's transverse part)");
  f.set_attribute("/film", "mean_thickness_m", ff.mean_thickness.mean_m);
  f.set_attribute("/film", "mean_thickness_std_m", ff.mean_thickness.std_m);
  std::vector<double> tm, ts;
  for (const auto& s : ff.section_thickness) {
    tm.push_back(s.mean_m);
    ts.push_back(s.std_m);
  }
  f.write("/film/section_z", ff.section_z, "m");
  f.write("/film/thickness_mean", tm, "m");
  f.write("/film/thickness_std", ts, "m");
  f.write("/film/bin_theta", ff.bin_theta, "rad");
  f.write("/film/surface_axial_velocity", ff.surface_velocity, "m/s");
  std::vector<double> moving(ff.zones.zone_of_bin.begin(), ff.zones.zone_of_bin.end());
  f.write("/film/moving_zone_of_bin", moving, "1");
  std::vector<double> arc_theta, arc_z;
  for (const auto& a : ff.arcs) {
    arc_theta.push_back(a.theta);
    arc_z.push_back(a.z_over_length);
  }
  f.write("/film/arc_theta", arc_theta, "rad");
  f.write("/film/arc_z_over_length", arc_z, "1");
  f.write("/film/wall_distance_d", ff.bin_centre_d, "d");
  write_profiles(f, "/film/axial_velocity", ff.velocity_profiles, "m/s");
  write_profiles(f, "/film/solid_fraction", ff.solid_fraction, "1");
  f.set_attribute("/film/solid_fraction_mean", "rows", "0 = stationary zone, 1 = moving zone");
  // Dispersion: D from the slope of the MSD (docs/film_sampling.md "Wall-normal dispersion"),
  // with the lags and the axial window it used.
  std::vector<double> dc, ds, dd, lo, hi, tx, msd, msd_n;
  for (const auto& b : ff.dispersion) {
    dc.push_back(b.coefficient);
    ds.push_back(b.coefficient_std);
    dd.push_back(b.drift);
    lo.push_back(b.fit_lag_min);
    hi.push_back(b.fit_lag_max);
    tx.push_back(b.crossing_time);
    msd.insert(msd.end(), b.msd.begin(), b.msd.end());
    for (std::size_t n : b.msd_samples) msd_n.push_back(static_cast<double>(n));
  }
  f.write("/film/dispersion", dc, "m2/s");
  f.write("/film/dispersion_std", ds, "m2/s");
  f.write("/film/dispersion_drift", dd, "m/s");
  f.write("/film/dispersion_fit_lag_min", lo, "s");
  f.write("/film/dispersion_fit_lag_max", hi, "s");
  f.write("/film/dispersion_crossing_time", tx, "s");
  f.write("/film/dispersion_lags", ff.dispersion_lags, "s");
  const std::size_t nlag = ff.dispersion_lags.size();
  if (!ff.dispersion.empty() && nlag > 0 && msd.size() == ff.dispersion.size() * nlag) {
    f.write("/film/dispersion_msd", msd, {ff.dispersion.size(), nlag}, "m2");
    f.write("/film/dispersion_msd_samples", msd_n, {ff.dispersion.size(), nlag}, "1");
    for (const char* name : {"dispersion_msd", "dispersion_msd_samples"}) {
      f.attach_scale(std::string("/film/") + name, 0, "/film/wall_distance_d", "wall distance");
      f.attach_scale(std::string("/film/") + name, 1, "/film/dispersion_lags", "lag");
    }
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
  f.write("/film/ring_z", ff.ring_z, "m");
  write_profiles(f, "/film/ring_solid_fraction", ff.ring_solid_fraction, "1");
  write_profiles(f, "/film/ring_volume_flux", ff.ring_volume_flux, "m/s");
  f.set_attribute("/film/ring_volume_flux_mean", "meaning",
                  "phi * u over the whole circumference per axial section (rows) and wall-distance bin; "
                  "axial mass flow of a section = rho_s * sum over bins of this * shell area");
  for (const char* name : {"thickness_mean", "thickness_std"})
    f.attach_scale(std::string("/film/") + name, 0, "/film/section_z", "z");
  for (const char* name : {"surface_axial_velocity", "moving_zone_of_bin"})
    f.attach_scale(std::string("/film/") + name, 0, "/film/bin_theta", "theta");
  for (const char* name : {"dispersion", "dispersion_std", "dispersion_drift", "dispersion_fit_lag_min",
                           "dispersion_fit_lag_max", "dispersion_crossing_time"})
    f.attach_scale(std::string("/film/") + name, 0, "/film/wall_distance_d", "wall distance");
  for (const char* name : {"axial_velocity_mean", "axial_velocity_std", "axial_velocity_turns"}) {
    f.attach_scale(std::string("/film/") + name, 0, "/film/arc_theta", "arc theta");
    f.attach_scale(std::string("/film/") + name, 0, "/film/arc_z_over_length", "arc z/L");
  }
  for (const char* name : {"ring_solid_fraction_mean", "ring_solid_fraction_std", "ring_solid_fraction_turns",
                           "ring_volume_flux_mean", "ring_volume_flux_std", "ring_volume_flux_turns"}) {
    f.attach_scale(std::string("/film/") + name, 0, "/film/ring_z", "z");
    f.attach_scale(std::string("/film/") + name, 1, "/film/wall_distance_d", "wall distance");
  }
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
  const std::vector<double> t = f.read("/mass_flow/time"), fed = f.read("/mass_flow/fed"), out = f.read("/mass_flow/out");
  if (fed.size() != t.size() || out.size() != t.size()) throw std::runtime_error("/mass_flow: time, fed and out differ in length");
  const std::vector<double> hold = f.read("/mass_flow/holdup"), n = f.read("/mass_flow/particles"),
                            axial = f.read("/mass_flow/slice_axial_flow");
  if (hold.size() != t.size() || n.size() != t.size() || axial.size() != t.size())
    throw std::runtime_error("/mass_flow: holdup, particles and slice_axial_flow differ in length from time");
  std::vector<dem::scene::MassFlowSample> log(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    log[k].time = t[k];
    log[k].fed = fed[k];
    log[k].out = out[k];
    log[k].holdup = hold[k];
    log[k].particles = static_cast<std::int64_t>(n[k]);
    log[k].axial_flow = axial[k];
  }
  return log;
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
