#include "io/dem_output_h5.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/atomic_write.hpp"
#include "io/code_version.hpp"
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
  std::vector<double> dc, ds, dd;
  for (const auto& b : ff.dispersion) {
    dc.push_back(b.coefficient);
    ds.push_back(b.coefficient_std);
    dd.push_back(b.drift);
  }
  f.write("/film/dispersion", dc, "m^2/s");
  f.write("/film/dispersion_std", ds, "m^2/s");
  f.write("/film/dispersion_drift", dd, "m/s");
  f.set_attribute("/film/dispersion", "lag_s", ff.dispersion_lag);
  f.write("/film/ring_z", ff.ring_z, "m");
  write_profiles(f, "/film/ring_solid_fraction", ff.ring_solid_fraction, "1");
  write_profiles(f, "/film/ring_volume_flux", ff.ring_volume_flux, "m/s");
  f.set_attribute("/film/ring_volume_flux_mean", "meaning",
                  "phi * u over the whole circumference per axial section (rows) and wall-distance bin; "
                  "axial mass flow of a section = rho_s * sum over bins of this * shell area");
}

void write_snapshot(H5File& f, const NamedSnapshot& s) {
  const std::string g = "/snapshots/" + s.name;
  f.create_group(g);
  const auto& d = s.data;
  const std::size_t n = d.x.size();
  std::vector<double> pos(3 * n), vel(3 * n), id(n);
  for (std::size_t i = 0; i < n; ++i) {
    pos[3 * i] = d.x[i], pos[3 * i + 1] = d.y[i], pos[3 * i + 2] = d.z[i];
    vel[3 * i] = d.vx[i], vel[3 * i + 1] = d.vy[i], vel[3 * i + 2] = d.vz[i];
    id[i] = static_cast<double>(d.id[i]);
  }
  f.write(g + "/position", pos, {n, 3}, "m");
  f.write(g + "/velocity", vel, {n, 3}, "m/s");
  f.write(g + "/radius", d.radius, "m");
  f.write(g + "/id", id, "1");
  f.set_attribute(g, "time", d.time);
}

std::string xdmf(const std::vector<NamedSnapshot>& snaps) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& s : snaps) {
    const std::size_t n = s.data.x.size();
    const std::string g = "dem.h5:/snapshots/" + s.name;
    x << "   <Grid Name=\"" << s.name << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << s.data.time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\"/>\n"
      << "    <Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"" << n
      << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << g << "/position</DataItem></Geometry>\n"
      << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\"><DataItem Dimensions=\"" << n
      << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << g << "/velocity</DataItem></Attribute>\n"
      << "    <Attribute Name=\"radius\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem Dimensions=\"" << n
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << g << "/radius</DataItem></Attribute>\n"
      << "    <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem Dimensions=\"" << n
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << g << "/id</DataItem></Attribute>\n"
      << "   </Grid>\n";
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

void write_dem_h5(const std::string& dir, const std::string& case_path, const std::string& resolved_yaml,
                  const dem::scene::SceneConfig& scene, const DemRunResult& run) {
  H5File f = H5File::create(dir + "/dem.h5");
  f.set_attribute("/", "code_version", centrec::io::code_version());
  f.set_attribute("/", "engine", run.engine);
  f.set_attribute("/", "engine_version", run.engine_version);
  f.set_attribute("/", "case", case_path);
  f.set_attribute("/", "resolved_config", resolved_yaml);
  f.set_attribute("/", "drum_radius_m", 0.5 * scene.drum.diameter);
  f.set_attribute("/", "particle_diameter_m", scene.particle.diameter);
  f.set_attribute("/", "turn_period_s", dem::scene::turn_period(scene));
  write_mass_flow(f, run.mass_flow);
  write_film(f, run.fields);
  f.create_group("/snapshots");
  for (const auto& s : run.snapshots) write_snapshot(f, s);
  f.commit();
  write_text_atomically(dir + "/dem.xmf", xdmf(run.snapshots));
}

}  // namespace centrec::io
