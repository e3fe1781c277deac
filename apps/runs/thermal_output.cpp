#include "runs/thermal_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <sstream>

#include "io/atomic_write.hpp"
#include "thermal/particle_data.hpp"
#include "io/code_version.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "runs/provenance.hpp"

namespace centrec::runs {

namespace {
nlohmann::json stats_json(const thermal::SolverStats& s) {
  return {{"bdf_steps", s.steps},
          {"rhs_evaluations", s.rhs_evals},
          {"newton_iterations", s.newton_iterations},
          {"newton_convergence_failures", s.newton_failures},
          {"error_test_failures", s.error_test_failures},
          {"jacobian_evaluations", s.jacobian_evals},
          {"linear_solver_setups", s.linear_setups}};
}

nlohmann::json balance_json(const thermal::FilmBalance& b) {
  return {{"incident", b.incident},       {"absorbed", b.absorbed},
          {"emitted", b.emitted},         {"convected", b.convected},
          {"wall", b.wall},               {"carried_by_particles", b.carried},
          {"inlet_conduction", b.inlet_conduction}, {"storage_rate", b.storage},
          {"balance_residual", b.residual}};
}

// A unit as a column-name suffix: "W/(m K)" -> "W_mK", "W/m2" -> "W_m2".
std::string csv_unit(const std::string& units) {
  std::string u;
  for (const char ch : units)
    if (ch == '/') u += '_';
    else if (ch != '(' && ch != ')' && ch != ' ') u += ch;
  return u;
}

// Mean solar flux over a plane that the power crosses (W/m2; 0 for a plane of no area).
double mean_flux(double power, double area) { return area > 0 ? power / area : 0.0; }

// The receiver's power flow (W): what enters through the aperture and where it goes, and the
// solar flux quoted at both planes, the film and the aperture (docs/cavity_model.md).
nlohmann::json receiver_json(const config::ThermalCase& c, const thermal::FilmBalance& b,
                             const thermal::FilmOperator& op) {
  const double P = b.aperture_power;
  nlohmann::json j = {{"radiation_model", c.model.cavity.enabled ? "cavity" : "open_surface"},
                      {"aperture_power_W", P},
                      {"film_area_m2", op.film_area()},
                      {"flux_film_mean_W_m2", mean_flux(b.incident, op.film_area())},
                      {"carried_W", b.carried},
                      {"reflected_loss_W", b.reflected_loss},
                      {"emitted_loss_W", b.emitted_loss},
                      {"convective_loss_W", b.convected + b.walls_convected},
                      {"wall_loss_W", b.wall + b.walls_insulation},
                      {"inlet_conduction_W", b.inlet_conduction},
                      {"storage_rate_W", b.storage},
                      {"efficiency", b.efficiency},
                      {"h_convection_W_m2K", b.h_cavity},
                      {"balance_residual_W", b.receiver_residual},
                      {"balance_residual_relative", b.receiver_residual / thermal::receiver_balance_scale(b)}};
  if (c.model.cavity.enabled) {
    j["aperture_area_m2"] = op.aperture_area();
    j["flux_aperture_mean_W_m2"] = mean_flux(P, op.aperture_area());
    j["cavity_walls_convective_loss_W"] = b.walls_convected;
    j["cavity_walls_insulation_loss_W"] = b.walls_insulation;
    // The receiver's own losses when the case turns them on (docs/cavity_model.md).
    const thermal::CavitySettings& cs = c.model.cavity;
    if (cs.spillage > 0) j["spillage_loss_W"] = b.spillage_loss;
    if (cs.convection_correlation && (cs.wind_speed > 0 || cs.rotation_rad_s > 0))
      j["convection_parts"] = {{"h_natural_W_m2K", b.h_natural}, {"h_wind_W_m2K", b.h_wind},
                               {"h_rotation_W_m2K", b.h_rotation}, {"grashof", b.grashof},
                               {"reynolds_wind", b.reynolds_wind}, {"reynolds_rotation", b.reynolds_rotation},
                               {"mixing_exponent", cs.mixing_exponent}};
  } else {
    j["loss_factor"] = c.model.surface.loss_factor;
  }
  return j;
}

// One named column of a table of records, for writing records as 1D datasets.
template <class Record>
struct Column {
  const char* name;
  const char* units;
  double (*get)(const Record&);
};

template <class Record, std::size_t N>
void write_columns(io::H5File& f, const std::string& prefix, const std::vector<Record>& rows,
                   const Column<Record> (&columns)[N]) {
  for (const Column<Record>& c : columns) {
    std::vector<double> v;
    v.reserve(rows.size());
    for (const Record& r : rows) v.push_back(c.get(r));
    f.write(prefix + c.name, v, c.units);
  }
}

// The per-column series of the steady state ([nz], /grid/z their scale): written to /steady
// of thermal.h5 and results.h5 and as columns of DIR/along_z.csv, from this one list.
struct ColumnSeries {
  const char* name;
  const char* units;
  const std::vector<double> thermal::ThermalFields::*values;
};
const ColumnSeries kColumnSeries[] = {{"T_mixing_cup", "K", &thermal::ThermalFields::T_mixing_cup},
                                      {"T_surface", "K", &thermal::ThermalFields::T_surface},
                                      {"q_absorbed", "W/m2", &thermal::ThermalFields::q_absorbed},
                                      {"q_emitted", "W/m2", &thermal::ThermalFields::q_emitted},
                                      {"q_convected", "W/m2", &thermal::ThermalFields::q_convected},
                                      {"q_wall", "W/m2", &thermal::ThermalFields::q_wall}};

// Per-section k_eff and its parts (/steady/keff and columns of along_z.csv).
const Column<thermal::KeffSection> kKeffColumns[] = {
    {"z", "m", [](const auto& s) { return s.z; }},
    {"k_eff", "W/(m K)", [](const auto& s) { return s.k_eff; }},
    {"bed_conduction", "W/(m K)", [](const auto& s) { return s.bed_conduction; }},
    {"radiation", "W/(m K)", [](const auto& s) { return s.radiation; }},
    {"mixing", "W/(m K)", [](const auto& s) { return s.mixing; }},
    {"moving_thickness", "m", [](const auto& s) { return s.moving_thickness; }}};

// The fields results.xmf and thermal.xmf show, as flat [nz * nxi] copies in /xdmf: XDMF
// readers take point data in point order, one dimension (meshio does not reshape).
struct XdmfField {
  const char* name;
  const char* units;
};
const XdmfField kXdmfFields[] = {{"T", "K"},         {"k_n", "W/(m K)"}, {"k_bed", "W/(m K)"}, {"k_rad", "W/(m K)"},
                                 {"k_mix", "W/(m K)"}, {"u", "m/s"},        {"phi", "1"},         {"D", "m2/s"}};

}  // namespace

double section_mean(const std::vector<thermal::KeffSection>& k, double thermal::KeffSection::*m) {
  double s = 0.0;
  for (const auto& x : k) s += x.*m;
  return k.empty() ? 0.0 : s / k.size();
}

void write_thermal_h5(const std::string& path, const config::ThermalCase& c, const ThermalRun& r) {
  io::H5File f = io::H5File::create(path);
  write_thermal_groups(f, c, r, case_provenance(c.path, c.resolved_yaml));
  f.commit();
  const std::string xmf = path.substr(0, path.rfind('.')) + ".xmf";
  io::write_text_atomically(xmf, thermal_xdmf(std::filesystem::path(path).filename().string(), r));
}

std::string thermal_xdmf(const std::string& h5_name, const ThermalRun& r) {
  const thermal::FilmGrid& g = r.op->grid();
  const std::string n = std::to_string(g.nz * g.nxi);
  const std::string cells = std::to_string((g.nz - 1) * (g.nxi - 1));
  auto item = [&](const std::string& dims, const char* type, const std::string& path) {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"8\" Format=\"HDF\">" +
           h5_name + ":" + path + "</DataItem>";
  };
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n  <Grid Name=\"film\" GridType=\"Uniform\">\n"
    << "   <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << cells << "\">"
    << item(cells + " 4", "Int", "/grid/quads") << "</Topology>\n"
    << "   <Geometry GeometryType=\"XYZ\">" << item(n + " 3", "Float", "/grid/points") << "</Geometry>\n";
  for (const XdmfField& field : kXdmfFields)
    x << "   <Attribute Name=\"" << field.name << "\" AttributeType=\"Scalar\" Center=\"Node\">"
      << item(n, "Float", std::string("/xdmf/") + field.name) << "</Attribute>\n";
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x.str();
}

std::string along_z_csv(const ThermalRun& r) {
  const thermal::FilmGrid& g = r.op->grid();
  std::ostringstream c;
  c.precision(10);
  c << "z_m,thickness_m";
  for (const ColumnSeries& s : kColumnSeries) c << ',' << s.name << '_' << csv_unit(s.units);
  for (std::size_t k = 1; k < std::size(kKeffColumns); ++k)
    c << ",keff_" << kKeffColumns[k].name << '_' << csv_unit(kKeffColumns[k].units);
  c << '\n';
  for (std::size_t i = 0; i < static_cast<std::size_t>(g.nz); ++i) {
    c << g.zc[i] << ',' << g.tc[i];
    for (const ColumnSeries& s : kColumnSeries) c << ',' << (r.fields.*s.values)[i];
    for (std::size_t k = 1; k < std::size(kKeffColumns); ++k) c << ',' << kKeffColumns[k].get(r.keff[i]);
    c << '\n';
  }
  return c.str();
}

std::string film_profiles_csv(const thermal::FilmField& film) {
  std::ostringstream c;
  c.precision(10);
  c << "z_m,eta_m,inside_film,u_m_s,phi,D_m2_s\n";
  const std::size_t ne = film.neta();
  for (std::size_t i = 0; i < film.nz(); ++i)
    for (std::size_t j = 0; j < ne; ++j)
      c << film.z[i] << ',' << film.eta[j] << ',' << (film.eta[j] <= film.t[i] ? 1 : 0) << ','
        << film.u[i * ne + j] << ',' << film.phi[i * ne + j] << ',' << film.D[i * ne + j] << '\n';
  return c.str();
}

void write_thermal_groups(io::H5File& f, const config::ThermalCase& c, const ThermalRun& r, const io::Provenance& p) {
  io::write_provenance(f, p);
  f.set_attribute("/", "title", c.title);
  f.set_attribute("/", "film_source", c.film_source.text());
  const thermal::FilmGrid& g = r.op->grid();
  const std::size_t nz = g.nz, nxi = g.nxi;
  std::vector<double> xi(nxi), eta(nz * nxi);
  for (std::size_t j = 0; j < nxi; ++j) xi[j] = (j + 0.5) / nxi;
  for (std::size_t i = 0; i < nz; ++i)
    for (std::size_t j = 0; j < nxi; ++j) eta[i * nxi + j] = g.eta_center(i, j);
  f.write("/grid/z", g.zc, "m");
  f.write("/grid/xi", xi, "1");
  f.write("/grid/thickness", g.tc, "m");
  f.write("/grid/eta", eta, {nz, nxi}, "m");
  f.write("/grid/u", g.u, {nz, nxi}, "m/s");
  f.write("/grid/phi", g.phi, {nz, nxi}, "1");
  f.write("/grid/D", g.D, {nz, nxi}, "m2/s");
  // The grid for XDMF readers (thermal_xdmf): cell centres (z, eta, 0) and the quadrilaterals
  // between neighbouring centres.
  std::vector<double> points;
  std::vector<std::int64_t> quads;
  for (std::size_t i = 0; i < nz; ++i)
    for (std::size_t j = 0; j < nxi; ++j) {
      points.insert(points.end(), {g.zc[i], eta[i * nxi + j], 0.0});
      if (i + 1 < nz && j + 1 < nxi) {
        const auto a = static_cast<std::int64_t>(i * nxi + j), b = a + static_cast<std::int64_t>(nxi);
        quads.insert(quads.end(), {a, b, b + 1, a + 1});
      }
    }
  f.write("/grid/points", points, {nz * nxi, 3}, "m");
  f.write_int64("/grid/quads", quads, {quads.size() / 4, 4}, "1");
  const thermal::ThermalFields& fl = r.fields;
  f.write("/steady/T", fl.T, {nz, nxi}, "K");
  f.write("/steady/k_n", fl.k_n, {nz, nxi}, "W/(m K)");
  f.write("/steady/k_bed", fl.k_bed, {nz, nxi}, "W/(m K)");
  f.write("/steady/k_rad", fl.k_rad, {nz, nxi}, "W/(m K)");
  f.write("/steady/k_mix", fl.k_mix, {nz, nxi}, "W/(m K)");
  f.attach_scale("/grid/thickness", 0, "/grid/z", "z");
  for (const ColumnSeries& c : kColumnSeries) {
    f.write(std::string("/steady/") + c.name, fl.*c.values, c.units);
    f.attach_scale(std::string("/steady/") + c.name, 0, "/grid/z", "z");
  }
  // Per-section k_eff and the transient series: one column per member, written in a loop.
  write_columns(f, "/steady/keff/", r.keff, kKeffColumns);
  for (const char* name : {"k_eff", "bed_conduction", "radiation", "mixing", "moving_thickness"})
    f.attach_scale(std::string("/steady/keff/") + name, 0, "/steady/keff/z", "z");
  for (const char* name : {"/grid/eta", "/grid/u", "/grid/phi", "/grid/D", "/steady/T", "/steady/k_n", "/steady/k_bed",
                           "/steady/k_rad", "/steady/k_mix"}) {
    f.attach_scale(name, 0, "/grid/z", "z");
    f.attach_scale(name, 1, "/grid/xi", "xi");
  }
  if (!fl.cavity_T.empty()) {
    // Enclosure surfaces: rings (z = 0 .. L), back plate, front annulus (if any); their axial
    // positions as the dimension scale (the back plate at 0, the annulus at L).
    f.write("/steady/cavity/surface_z", r.op->cavity_surface_z(), "m");
    f.set_attribute("/steady/cavity", "surfaces",
                    "the film's rings from the back (z = ring centre), then the back plate (z = 0), then the front "
                    "annulus if the aperture is smaller than the drum (z = L)");
    const struct {
      const char* name;
      const std::vector<double>& values;
      const char* units;
    } per_surface[] = {{"T", fl.cavity_T, "K"},
                       {"solar_irradiation", fl.cavity_solar_irradiation, "W/m2"},
                       {"thermal_irradiation", fl.cavity_thermal_irradiation, "W/m2"}};
    for (const auto& q : per_surface) {
      f.write(std::string("/steady/cavity/") + q.name, q.values, q.units);
      f.attach_scale(std::string("/steady/cavity/") + q.name, 0, "/steady/cavity/surface_z", "surface");
    }
  }
  const std::vector<double>* xdmf_values[] = {&fl.T, &fl.k_n, &fl.k_bed, &fl.k_rad, &fl.k_mix, &g.u, &g.phi, &g.D};
  static_assert(sizeof(xdmf_values) / sizeof(xdmf_values[0]) == std::size(kXdmfFields), "one array per XDMF field");
  for (std::size_t k = 0; k < std::size(kXdmfFields); ++k)
    f.write(std::string("/xdmf/") + kXdmfFields[k].name, *xdmf_values[k], kXdmfFields[k].units);
  f.set_attribute("/xdmf", "description", "flat copies of the /steady and /grid fields in point order for thermal.xmf / "
                                          "results.xmf (points: /grid/points, cells: /grid/quads)");
  f.set_attribute("/steady", "T_out_K", r.balance.T_out);
  f.set_attribute("/steady", "efficiency", r.balance.efficiency);
  f.set_attribute("/steady", "aperture_power_W", r.balance.aperture_power);
  f.set_attribute("/steady", "reflected_loss_W", r.balance.reflected_loss);
  f.set_attribute("/steady", "emitted_loss_W", r.balance.emitted_loss);
  f.set_attribute("/steady", "convective_loss_W", r.balance.convected + r.balance.walls_convected);
  f.set_attribute("/steady", "wall_loss_W", r.balance.wall + r.balance.walls_insulation);
  f.set_attribute("/steady", "receiver_balance_residual_W", r.balance.receiver_residual);
  if (r.has_transient) {
    const Column<thermal::TransientSample> series[] = {
        {"t", "s", [](const auto& s) { return s.t; }},
        {"T_out", "K", [](const auto& s) { return s.balance.T_out; }},
        {"absorbed", "W", [](const auto& s) { return s.balance.absorbed; }},
        {"emitted", "W", [](const auto& s) { return s.balance.emitted; }},
        {"convected", "W", [](const auto& s) { return s.balance.convected; }},
        {"wall", "W", [](const auto& s) { return s.balance.wall; }},
        {"carried", "W", [](const auto& s) { return s.balance.carried; }},
        {"aperture_power", "W", [](const auto& s) { return s.balance.aperture_power; }},
        {"reflected_loss", "W", [](const auto& s) { return s.balance.reflected_loss; }},
        {"emitted_loss", "W", [](const auto& s) { return s.balance.emitted_loss; }},
        {"efficiency", "1", [](const auto& s) { return s.balance.efficiency; }},
        {"storage_rate", "W", [](const auto& s) { return s.balance.storage; }},
        {"T_surface_max", "K", [](const auto& s) { return s.T_surface_max; }},
        {"mass_flow", "kg/s", [](const auto& s) { return s.balance.mass_flow; }}};
    write_columns(f, "/transient/", r.transient.samples, series);
    for (const auto& c : series)
      if (std::string(c.name) != "t") f.attach_scale(std::string("/transient/") + c.name, 0, "/transient/t", "t");
    f.write("/transient/T_final", r.transient.y_end, {nz, nxi}, "K");
  }
  io::write_film_field(f, c.film, "/film");
}

std::vector<std::string> thermal_warnings(const config::ThermalCase& c, const ThermalRun& r) {
  std::vector<std::string> w;
  const thermal::ParticleData& particle = thermal::particle_data(c.particle);
  const double T_out = r.balance.T_out;
  const double T_peak = r.fields.T.empty() ? T_out : *std::max_element(r.fields.T.begin(), r.fields.T.end());
  if (T_peak > particle.T_max || T_out > particle.T_max) {
    char b[300];
    std::snprintf(b, sizeof b,
                  "the film reaches %.1f K (outlet %.1f K), above the %.1f K %s's data hold (docs/particle_data.md): "
                  "the properties there are extrapolated",
                  T_peak, T_out, particle.T_max, c.particle.c_str());
    w.push_back(b);
  }
  return w;
}

nlohmann::json thermal_summary(const config::ThermalCase& c, const ThermalRun& r) {
  const thermal::FilmBalance& b = r.balance;
  const thermal::FilmGrid& g = r.op->grid();
  nlohmann::json j;
  j["centrec_version"] = centrec::io::code_version();
  j["case"] = c.path;
  j["title"] = c.title;
  j["film_source"] = c.film_source.text();
  j["model"] = {{"kind", c.grid.lumped ? "1d" : "2d"},
                {"nz", g.nz},
                {"nxi", g.nxi},
                {"advection", c.grid.advection == thermal::Advection::upwind ? "upwind" : "van_leer"}};
  j["T_in_K"] = c.model.T_in;
  j["T_out_K"] = b.T_out;
  j["T_out_C"] = b.T_out - 273.15;
  j["T_surface_max_K"] = *std::max_element(r.fields.T_surface.begin(), r.fields.T_surface.end());
  j["mass_flow_kg_s"] = b.mass_flow;
  // The inputs that define the point, as plain keys (a coupled run adds its DEM's).
  j["point"] = {{"speed_rpm", nullptr},
                {"mass_flow_kg_s", b.mass_flow},
                {"T_in_K", c.model.T_in},
                {"flux_film_mean_W_m2", mean_flux(b.incident, r.op->film_area())},
                {"seed", nullptr},
                {"dt_s", nullptr}};
  j["efficiency"] = b.efficiency;
  j["warnings"] = thermal_warnings(c, r);  // a coupled run adds what it allowed
  j["powers_W"] = balance_json(b);
  j["receiver"] = receiver_json(c, b, *r.op);
  j["balance_residual_relative"] = b.residual / thermal::film_balance_scale(b);
  j["mass_flux_max_correction"] = g.max_flux_correction;
  nlohmann::json k;
  k["film_mean"] = {{"k_eff", section_mean(r.keff, &thermal::KeffSection::k_eff)},
                    {"bed_conduction", section_mean(r.keff, &thermal::KeffSection::bed_conduction)},
                    {"radiation", section_mean(r.keff, &thermal::KeffSection::radiation)},
                    {"mixing", section_mean(r.keff, &thermal::KeffSection::mixing)}};
  // Up to 10 evenly spaced sections (all sections are in thermal.h5 /steady/keff).
  nlohmann::json sections = nlohmann::json::array();
  const std::size_t step = std::max<std::size_t>(1, r.keff.size() / 10);
  for (std::size_t i = step / 2; i < r.keff.size(); i += step) {
    const auto& s = r.keff[i];
    sections.push_back({{"z_m", s.z},
                        {"k_eff", s.k_eff},
                        {"bed_conduction", s.bed_conduction},
                        {"radiation", s.radiation},
                        {"mixing", s.mixing}});
  }
  k["sections"] = sections;
  k["units"] = "W/(m K)";
  j["k_eff"] = k;
  j["solver"]["steady"] = stats_json(r.steady.stats);
  j["solver"]["steady"]["newton_polish_iterations"] = r.steady.newton_iterations;
  j["solver"]["steady"]["marched"] = r.steady.marched;
  j["solver"]["steady"]["march_time_s"] = r.steady.march_time;
  j["solver"]["steady"]["scaled_residual"] = r.steady.residual;
  // The tolerance the residual was held to: thermal.solver.steady_tolerance, or the round-off
  // floor's multiple where that is larger (thermal/steady_state.hpp, docs/thermal_model.md).
  j["solver"]["steady"]["tolerance_applied"] = r.steady.tolerance;
  j["solver"]["steady"]["residual_floor"] = r.steady.residual_floor;
  j["solver"]["steady"]["wall_time_s"] = r.steady_seconds;
  if (r.has_transient) {
    const TransientOutlet o = transient_outlet(r);
    j["transient"] = {{"t_end_s", o.t_end},
                      {"T_out_start_K", o.T_start},
                      {"T_out_end_K", o.T_end},
                      {"T_out_min_K", o.T_min},
                      {"T_out_max_K", o.T_max}};
    j["solver"]["transient"] = stats_json(r.transient.stats);
    j["solver"]["transient"]["wall_time_s"] = r.transient_seconds;
  }
  return j;
}

TransientOutlet transient_outlet(const ThermalRun& r) {
  const auto& s = r.transient.samples;
  TransientOutlet o{s.back().t, s.front().balance.T_out, s.back().balance.T_out, s.front().balance.T_out,
                    s.front().balance.T_out};
  for (const auto& x : s) {
    o.T_min = std::min(o.T_min, x.balance.T_out);
    o.T_max = std::max(o.T_max, x.balance.T_out);
  }
  return o;
}

std::string efficiency_text(double efficiency) {
  if (std::isnan(efficiency)) return "not defined (the aperture power is below 1e-6 of the balance's largest power)";
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", efficiency);
  return b;
}

void print_receiver_report(const config::ThermalCase& c, const ThermalRun& r) {
  const thermal::FilmBalance& b = r.balance;
  const double P = b.aperture_power;
  const double A_film = r.op->film_area(), A_ap = r.op->aperture_area();
  if (c.model.cavity.enabled)
    std::printf("  solar flux: %.4g W/m2 mean on the film (first incidence, %.4g m2) = %.4g W/m2 mean through the "
                "aperture (%.4g m2)\n",
                mean_flux(b.incident, A_film), A_film, mean_flux(P, A_ap), A_ap);
  else
    std::printf("  solar flux: %.4g W/m2 mean on the film (%.4g m2; open surface: no aperture)\n",
                mean_flux(b.incident, A_film), A_film);
  // Shares of the aperture power, where there is sunlight to speak of (as the efficiency:
  // none below 1e-6 of the balance's largest power).
  const bool sunlit = P > 0 && P >= 1e-6 * thermal::receiver_balance_scale(b);
  auto pct = [P, sunlit](double x) {
    char t[32] = "no sunlight";
    if (sunlit) std::snprintf(t, sizeof t, "%.2f %%", 100.0 * x / P);
    return std::string(t);
  };
  for (const std::string& w : thermal_warnings(c, r)) std::printf("  WARNING: %s\n", w.c_str());
  std::printf("  receiver (%s): aperture %.6g W -> carried %.6g W, efficiency %s (carried / aperture power)\n",
              c.model.cavity.enabled ? "cavity" : "open surface", P, b.carried, efficiency_text(b.efficiency).c_str());
  std::printf("  losses: reflected %.4g W (%s), emitted %.4g W (%s) through the %s, convective %.4g W "
              "(%s, h %.3g W/(m2 K)), wall %.4g W (%s); balance residual %.2e of %s\n",
              b.reflected_loss, pct(b.reflected_loss).c_str(), b.emitted_loss, pct(b.emitted_loss).c_str(),
              c.model.cavity.enabled ? "aperture" : "open surface", b.convected + b.walls_convected,
              pct(b.convected + b.walls_convected).c_str(), b.h_cavity, b.wall + b.walls_insulation,
              pct(b.wall + b.walls_insulation).c_str(), b.receiver_residual / thermal::receiver_balance_scale(b),
              P >= thermal::receiver_balance_scale(b) ? "aperture power" : "the balance's largest power");
  const thermal::CavitySettings& cs = c.model.cavity;
  if (!c.model.cavity.enabled) return;
  if (cs.spillage > 0)
    std::printf("  spillage: %.4g W (%s) on the front plate's outer face, not entering\n", b.spillage_loss,
                pct(b.spillage_loss).c_str());
  if (cs.convection_correlation && (cs.wind_speed > 0 || cs.rotation_rad_s > 0))
    std::printf("  convection (docs/cavity_model.md): natural %.3g W/(m2 K) at Gr_L %.3g (extrapolated: fitted to large "
                "central-receiver cavities), wind %.3g W/(m2 K) at %.3g m/s (Re_ap %.3g), "
                "rotation %.3g W/(m2 K) at Re_r %.3g (correlated for 1.6e3-2.77e5%s); mixed n = %.2g: %.3g W/(m2 K)\n",
                b.h_natural, b.grashof, b.h_wind, cs.wind_speed, b.reynolds_wind, b.h_rotation, b.reynolds_rotation,
                b.reynolds_rotation > 2.77e5 || (b.reynolds_rotation > 0 && b.reynolds_rotation < 1.6e3) ? ", OUTSIDE" : "",
                cs.mixing_exponent, b.h_cavity);
}

}  // namespace centrec::runs
