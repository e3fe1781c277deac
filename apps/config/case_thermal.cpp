#include "config/case_thermal.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "config/case_file.hpp"
#include "coupling/film_mappings.hpp"
#include "io/film_field_h5.hpp"
#include "io/flux_table_csv.hpp"
#include "thermal/analytic_film.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/particle_data.hpp"

namespace centrec::config {

namespace th = centrec::thermal;

namespace {
std::string resolve_path(const std::string& case_dir, const std::string& p) {
  if (p.empty() || p[0] == '/' || case_dir.empty()) return p;
  return case_dir + "/" + p;
}

const Range kTemperature = Range::closed(1.0, 5000.0);  // K
// Values any solid has (CRC Handbook of Chemistry and Physics: conductivity up to diamond's
// ~2200 W/(m K), down to porous ceramics' ~0.01; density up to osmium's 22,590 kg/m3;
// specific heat from ~100 (heavy metals) to lithium's 3,580 J/(kg K)), with margin.
const Range kSolidConductivity = Range::closed(0.01, 2500.0);  // W/(m K)
const Range kSolidDensity = Range::closed(100.0, 25000.0);     // kg/m3
const Range kSolidHeatCapacity = Range::closed(50.0, 5000.0);  // J/(kg K)

// The particle's own values (thermal.particle, thermal/particle_data.hpp) are the defaults of
// k_s, alpha and epsilon; a value given here replaces the nominal one (its range stays the
// particle's in the error budget).
th::Material read_material(MapReader r, const th::Material& particle) {
  th::Material m = particle;
  m.rho_s = r.number("rho_s", m.rho_s, kSolidDensity, "kg/m3", "particle (solid) density");
  m.k_s = r.number("k_s", m.k_s, kSolidConductivity, "W/(m K)", "solid conductivity of a particle");
  m.alpha = r.number("alpha", m.alpha, Range::closed(0.0, 1.0), "", "solar absorptance of the film");
  m.epsilon = r.number("epsilon", m.epsilon, Range::open_closed(0.0, 1.0), "",
                       "thermal emissivity of the particles and the film surface");
  m.d = r.number("d", m.d, Range::open_closed(0.0, 0.05), "m",
                 "particle diameter (in a coupled case, that of dem.particles)");
  r.finish();
  return m;
}

void read_film(MapReader r, const std::string& case_dir, double particle_d, ThermalCase& c) {
  const bool analytic = r.has("analytic"), file = r.has("file");
  if (analytic == file) r.fail(analytic ? "file" : "analytic", "give exactly one of film.analytic or film.file");
  if (analytic) {
    MapReader a = r.child("analytic", "an analytic film: uniform thickness, a sheared velocity profile");
    th::AnalyticFilm af;
    af.d = particle_d;
    af.thickness = a.number("thickness", af.thickness, Range::open_closed(0.0, 0.5), "m",
                            "film thickness (more than one particle diameter)");
    if (!(af.thickness > af.d))
      a.fail("thickness", "must exceed one particle diameter (got " + std::to_string(af.thickness) +
                              " m, thermal.material.d = " + std::to_string(af.d) +
                              " m): the resting layer is one diameter thick");
    af.u_surface = a.number("u_surface", af.u_surface, Range::open_closed(0.0, 100.0), "m/s",
                            "axial velocity at the free surface");
    af.phi = a.number("phi", af.phi, Range::closed(0.05, 0.74), "", "solid volume fraction");
    af.D_uniform = a.number("D_uniform", af.D_uniform, Range::closed(0.0, 1.0), "m2/s",
                            "particle dispersion coefficient added everywhere");
    af.D_shear_coeff = a.number("D_shear_coeff", af.D_shear_coeff, Range::closed(0.0, 10.0), "",
                                "c in the shear dispersion D = c gamma_dot d^2");
    af.drum_diameter = a.number("drum_diameter", af.drum_diameter, Range::open_closed(0.0, 100.0), "m",
                                "diameter of the drum the film lines");
    af.length = a.number("length", af.length, Range::open_closed(0.0, 100.0), "m", "axial length of the film");
    // The film lines the drum's wall: thicker than the drum's radius it would cross the axis.
    if (!(af.thickness < 0.5 * af.drum_diameter))
      a.fail("thickness", "the film (" + std::to_string(af.thickness) + " m) must be thinner than the drum's radius (" +
                              std::to_string(0.5 * af.drum_diameter) + " m, film.analytic.drum_diameter / 2)");
    a.finish();
    c.film = th::analytic_film(af);
    c.film_source = {FilmSource::Kind::analytic, "", ""};
  } else {
    const std::string path = resolve_path(
        case_dir, r.string("file", "", "a stored film field (film.h5 of `centrec run`), relative to the case file"));
    const std::string group = r.string("group", "/film", "the HDF5 group of the film field in that file");
    try {
      c.film = io::read_film_field(io::H5File::open_read(path), group);
    } catch (const std::exception& e) {
      r.fail("file", e.what());
    }
    if (!(c.film.length > 0.0) || !(c.film.drum_diameter > 0.0))
      r.fail("file", path + ": the film field needs positive 'length' and 'drum_diameter' attributes");
    for (double t : c.film.t)
      if (!(t < 0.5 * c.film.drum_diameter))
        r.fail("file", path + ": the film is " + std::to_string(t) + " m thick in a drum of radius " +
                           std::to_string(0.5 * c.film.drum_diameter) + " m: it would cross the axis");
    if (c.film.particle_diameter > 0.0 && std::abs(c.film.particle_diameter / particle_d - 1.0) > 1e-6)
      r.fail("file", path + ": the film field is for particles of d = " + std::to_string(c.film.particle_diameter) +
                         " m but thermal.material.d = " + std::to_string(particle_d) + " m (mismatched film file)");
    c.film_source = {FilmSource::Kind::file, path, ""};
  }
  r.finish();
}

th::TimeFactor read_time_factor(MapReader r) {
  th::TimeFactor f;
  const std::string kind =
      r.choice("kind", "constant", {"constant", "step", "pulse"},
               "time history of the factor: constant 1, a ramped step to `level`, or a dip and back");
  f.kind = kind == "step"    ? th::TimeFactor::Kind::step
           : kind == "pulse" ? th::TimeFactor::Kind::pulse
                             : th::TimeFactor::Kind::constant;
  if (f.kind != th::TimeFactor::Kind::constant) {
    f.level = r.number("level", 1.0, Range::closed(0.0, 100.0), "", "the factor after the step (during the pulse)");
    f.t_start = r.number("t_start", 0.0, Range::non_negative(), "s", "start of the step or pulse");
    f.ramp = r.number("ramp", 0.0, Range::non_negative(), "s", "duration of each linear edge");
  }
  if (f.kind == th::TimeFactor::Kind::pulse) {
    f.t_end = r.number("t_end", f.t_start + f.ramp, Range::non_negative(), "s",
                       "start of the pulse's return edge (default t_start + ramp)");
    if (f.t_end < f.t_start + f.ramp) r.fail("t_end", "must be >= t_start + ramp (the dip must finish its first edge)");
  }
  r.finish();
  return f;
}

void read_flux(MapReader r, const std::string& case_dir, th::FilmModel& m) {
  const std::string profile =
      r.choice("profile", "uniform", {"uniform", "gaussian", "table"}, "shape of the solar flux along the drum");
  th::FluxProfile& f = m.flux;
  // The former keys named no plane and were read as the flux on the film; they are refused,
  // not reinterpreted, so a case written for them cannot silently change its power.
  const struct {
    const char* old_key;
    const char* message;
  } kRenamed[] = {
      {"q",
       "was renamed: give flux.q_film (W/m2, the sunlight's first incidence on the film: what flux.q meant) or "
       "flux.q_aperture (W/m2, the mean flux through the cavity's aperture)"},
      {"q_peak", "was renamed flux.q_film_peak (W/m2, the Gaussian's peak on the film: what flux.q_peak meant)"},
      {"q_base", "was renamed flux.q_film_base (W/m2, the uniform part on the film: what flux.q_base meant)"}};
  for (const auto& k : kRenamed)
    if (r.has(k.old_key)) r.fail(k.old_key, k.message);
  if (profile == "uniform") {
    f.kind = th::FluxProfile::Kind::uniform;
    if (r.has("q_film") && r.has("q_aperture"))
      r.fail("q_aperture", "give exactly one of flux.q_film (on the film) and flux.q_aperture (through the aperture)");
    if (r.has("q_aperture"))
      f.aperture_mean = r.number("q_aperture", 0.0, Range::closed(0.0, 1e8), "W/m2",
                                 "mean solar flux through the cavity's aperture (profile uniform, cavity model; "
                                 "spread uniformly over the film; instead of q_film)");
    else
      f.q = r.number("q_film", f.q, Range::closed(0.0, 2e7), "W/m2",
                     "uniform solar flux on the film (its first incidence; profile uniform; or give q_aperture)");
  } else if (profile == "gaussian") {
    f.kind = th::FluxProfile::Kind::gaussian;
    f.q = r.number("q_film_peak", f.q, Range::closed(0.0, 2e7), "W/m2", "peak of the Gaussian flux on the film");
    f.z_center = r.number("z_center", f.z_center, Range::any(), "m", "axial position of the peak");
    f.sigma = r.number("sigma", f.sigma, Range::positive(), "m", "standard deviation of the Gaussian along z");
    f.q_base =
        r.number("q_film_base", 0.0, Range::closed(0.0, 2e7), "W/m2", "uniform flux on the film added to the Gaussian");
  } else {
    f.kind = th::FluxProfile::Kind::table;
    const std::string path = resolve_path(
        case_dir, r.string("table_file", "", "CSV of z (m) and q (W/m2, on the film), relative to the case file"));
    try {
      io::read_flux_table_csv(path, f.table_z, f.table_q);
      f.check();
    } catch (const std::exception& e) {
      r.fail("table_file", e.what());
    }
  }
  // Solar absorption: Beer-Lambert below the surface (default; depth in particle diameters,
  // by default from the bed's solid fraction, thermal/film_model.hpp), uniform over n layers,
  // or at the surface.
  const std::string absorption = r.choice(
      "absorption", r.has("absorb_depth_layers") ? "layers" : "extinction", {"extinction", "layers", "surface"},
      "where the solar flux is absorbed: Beer-Lambert below the surface, uniformly over layers, or at "
      "the surface (default layers when absorb_depth_layers is given)");
  if (absorption == "layers")
    m.surface.absorb_depth_layers = r.number("absorb_depth_layers", 0.0, Range::closed(0.0, 20.0), "particle diameters",
                                             "depth over which the flux is absorbed uniformly");
  if (absorption == "extinction")
    m.surface.extinction_depth_d = r.number(
        "extinction_depth_d", -1.0, Range::closed(-1.0, 20.0), "particle diameters",
        "Beer-Lambert extinction depth (absorption extinction; -1: from the solid fraction, (1 - phi) / (1.5 phi))");
  if (m.surface.extinction_depth_d == 0.0 && absorption == "extinction")
    r.fail("extinction_depth_d", "must be > 0 (or omitted for the value from the solid fraction)");
  if (absorption == "extinction" && m.surface.extinction_depth_d < 0.0)
    m.surface.extinction_local =
        r.choice("extinction_phi", "local", {"local", "column_mean"},
                 "solid fraction of the Beer-Lambert depth from phi: each cell's own (the optical depth through a "
                 "loose top; docs/thermal_model.md), or the column's mean") == "local";
  m.flux_time = read_time_factor(r.child("time", "a time history multiplying the flux (needs thermal.transient)"));
  r.finish();
}

void read_conductivity(MapReader r, th::FilmModel& m) {
  const std::string model = r.choice("model", "zbs", {"zbs", "constant"},
                                     "bed conductivity: Zehner-Bauer-Schluender with radiation, or a constant k");
  if (model == "constant")
    m.conductivity.k_constant =
        r.required_number("k", Range::closed(1e-3, 2500.0), "W/(m K)", "the constant bed conductivity");
  m.bed.shape_factor =
      r.number("shape_factor", m.bed.shape_factor, Range::positive(), "", "ZBS shape factor C_f (1.25 for spheres)");
  m.bed.flattening = r.number("flattening", m.bed.flattening, Range::closed(0.0, 1.0), "",
                              "ZBS contact flattening coefficient (0.0077 for spheres)");
  m.bed.radiation = r.boolean("radiation", true, "add radiation between particles to the bed conductivity");
  m.conductivity.mixing =
      r.boolean("mixing", true, "add the particles' dispersion (rho_s phi c_p D) to the conductivity");
  const std::string axial = r.choice("axial", "bed", {"bed", "bed_and_mixing", "none"},
                                     "conduction along z: the bed's, the bed's with mixing, or none");
  m.conductivity.axial = axial == "none"  ? th::ConductivitySettings::Axial::none
                         : axial == "bed" ? th::ConductivitySettings::Axial::bed
                                          : th::ConductivitySettings::Axial::bed_and_mixing;
  r.finish();
}

// The front plate closing the drum's open end around the aperture (docs/cavity_model.md,
// "Front plate"); r_aperture is the same aperture as radiation.aperture_diameter / 2.
void read_front_plate(MapReader& rad, th::CavitySettings& cav) {
  MapReader p = rad.child("front_plate", "the annular front plate around the aperture at z = L (cavity model)");
  // A resolved configuration writes both keys, the unused one at its default 0.
  const double r_aperture =
      p.number("r_aperture", 0.0, Range::closed(0.0, 50.0), "m (0 = aperture_diameter / 2)",
               "inner radius of the front plate: the aperture's radius (instead of aperture_diameter)");
  if (r_aperture > 0.0) {
    if (cav.aperture_diameter > 0.0 && cav.aperture_diameter != 2.0 * r_aperture)
      p.fail("r_aperture", "give the aperture once: radiation.aperture_diameter or radiation.front_plate.r_aperture");
    cav.aperture_diameter = 2.0 * r_aperture;
  }
  cav.plate_U = p.number("U", -1.0, Range::closed(-1.0, 1e5), "W/(m2 K) (-1 = thermal.wall.U_w)",
                         "heat loss through the front plate's insulation to T_amb (0: adiabatic, reradiating)");
  cav.plate_absorptance = p.number("absorptance", -1.0, Range::closed(-1.0, 1.0), "(-1 = wall_absorptance)",
                                   "solar absorptance of the front plate's inner face");
  cav.plate_emissivity = p.number("emissivity", -1.0, Range::closed(-1.0, 1.0), "(-1 = wall_emissivity)",
                                  "thermal emissivity of the front plate's inner face");
  if (p.has("absorptance") && cav.plate_absorptance == 0.0)
    p.fail("absorptance", "must be in (0, 1] (or -1: the wall's)");
  if (p.has("emissivity") && cav.plate_emissivity == 0.0) p.fail("emissivity", "must be in (0, 1] (or -1: the wall's)");
  if (p.has("absorptance") && cav.plate_absorptance < 0.0 && cav.plate_absorptance != -1.0)
    p.fail("absorptance", "must be in (0, 1] (or -1: the wall's)");
  if (p.has("emissivity") && cav.plate_emissivity < 0.0 && cav.plate_emissivity != -1.0)
    p.fail("emissivity", "must be in (0, 1] (or -1: the wall's)");
  p.finish();
}

void read_solver(MapReader r, ThermalCase& c) {
  th::IntegratorSettings& in = c.steady.integrator;
  // Ranges are what double precision and BDF can deliver (1e-30 is refused here).
  in.rtol = r.number("rtol", 1e-5, Range::closed(1e-12, 1e-2), "", "CVODE relative tolerance of the steady march");
  in.atol = r.number("atol", 1e-3, Range::closed(1e-10, 10.0), "K", "CVODE absolute tolerance");
  in.max_steps = r.integer("max_steps", 50000, 10, 100000000, "most CVODE steps per solve");
  in.max_order = static_cast<int>(r.integer("max_order", 5, 1, 5, "highest BDF order"));
  in.linear_solver =
      r.choice("linear_solver", "band", {"band", "klu"}, "linear solver of the Newton iterations") == "klu"
          ? th::LinearSolver::klu
          : th::LinearSolver::band;
  c.steady.tolerance = r.number("steady_tolerance", 1e-10, Range::closed(1e-14, 1e-2), "",
                                "scaled residual at which the film counts as steady (docs/thermal_model.md)");
  c.steady.newton_first = r.boolean("newton_first", true, "try damped Newton from the start before marching");
  c.steady.max_time_factor = r.number("max_time_scales", 1e4, Range::closed(1.0, 1e9), "",
                                      "give up marching after this many system time scales");
  c.steady.max_wall_seconds = r.number("max_wall_time", 600.0, Range::closed(1.0, 1e7), "s",
                                       "wall-time budget of the steady solve (docs/reliability.md)");
  c.transient_settings.integrator = in;
  c.transient_settings.integrator.rtol =
      r.number("transient_rtol", 1e-6, Range::closed(1e-12, 1e-2), "", "CVODE relative tolerance of the transient");
  r.finish();
}
}  // namespace

void read_thermal_sections(MapReader& root, const std::string& case_dir, ThermalCase& c, bool film_from_dem) {
  MapReader t = root.child("thermal", "the film energy equation (docs/thermal_model.md)");
  th::FilmModel& m = c.model;
  std::vector<std::string> particles;
  for (const th::ParticleData& p : th::particle_table()) particles.push_back(p.name);
  c.particle = t.choice("particle", particles.front(), particles,
                        "the particle whose c_p(T), k_s, absorptance and emissivity (with their uncertainty ranges) "
                        "the film takes (docs/particle_data.md)");
  th::apply_particle(th::particle_data(c.particle), m.material, m.heat);
  m.material = read_material(t.child("material", "the particles' thermal properties (defaults: thermal.particle's)"),
                             m.material);
  if (film_from_dem && !root.has("film")) {
    c.film_source.kind = FilmSource::Kind::dem;
    c.film_source.mapping = coupling::film_mappings().front().name;
  } else {
    MapReader f = root.child("film",
                             "the film the thermal model heats: analytic or from a file (coupled cases: the DEM's, "
                             "through film.mapping)");
    if (film_from_dem && f.has("mapping")) {
      // The choices and their meanings are the registry's rows (coupling/film_mappings.hpp).
      std::vector<std::string> names;
      std::string meaning = "how the DEM's film becomes the thermal film (docs/coupling.md)";
      for (const coupling::FilmMappingEntry& e : coupling::film_mappings()) {
        names.push_back(e.name);
        meaning += std::string(names.size() == 1 ? ": " : "; ") + e.name + ", " + e.description;
      }
      c.film_source.kind = FilmSource::Kind::dem;
      c.film_source.mapping = f.choice("mapping", names.front(), names, meaning);
      f.finish();
    } else {
      read_film(f, case_dir, m.material.d, c);
    }
  }

  const std::string model =
      t.choice("model", "2d", {"2d", "1d"}, "2D film (z and depth) or 1D depth-lumped (quick estimate)");
  c.grid.lumped = model == "1d";
  MapReader g = t.child("grid", "the finite-volume grid");
  c.grid.nz = static_cast<int>(g.integer("nz", 200, 2, 100000, "cells along the drum"));
  if (!c.grid.lumped) c.grid.nxi = static_cast<int>(g.integer("nxi", 40, 2, 2000, "cells across the film depth (2d)"));
  // The band Jacobian holds about 3 nxi + 1 entries per cell: refuse a grid it cannot hold.
  const double cells = static_cast<double>(c.grid.nz) * (c.grid.lumped ? 1 : c.grid.nxi);
  const double bytes = cells * (3.0 * (c.grid.lumped ? 1 : c.grid.nxi) + 1.0) * 8.0;
  if (bytes > 4e9)
    g.fail(c.grid.lumped ? "nz" : "nxi", "a grid of " + std::to_string(static_cast<long long>(cells)) +
                                             " cells needs about " +
                                             std::to_string(static_cast<long long>(bytes / 1e9)) +
                                             " GB for its band Jacobian (at most 4): use fewer cells");
  g.finish();
  c.grid.advection = t.choice("advection", "van_leer", {"van_leer", "upwind"},
                              "advection scheme along z (van Leer: second order; upwind: first order)") == "upwind"
                         ? th::Advection::upwind
                         : th::Advection::van_leer;
  m.T_in = t.number("T_in", 873.15, kTemperature, "K", "particle inlet temperature (within thermal.particle's data)");
  const th::ParticleData& particle = th::particle_data(c.particle);
  if (m.T_in < particle.T_min || m.T_in > particle.T_max) {
    char why[256];
    std::snprintf(why, sizeof why,
                  "%g K lies outside the range %s's data hold (c_p, k_s, absorptance, emissivity: %g-%g K, "
                  "docs/particle_data.md)",
                  m.T_in, c.particle.c_str(), particle.T_min, particle.T_max);
    t.fail("T_in", why);
  }
  read_conductivity(t.child("conductivity", "effective conductivity of the film"), m);
  MapReader hc = t.child("heat_capacity", "the particles' specific heat");
  if (hc.choice("model", "particle", {"particle", "constant"}, "c_p(T) of thermal.particle, or a constant") ==
      "constant")
    m.heat.cp_constant = hc.required_number("cp", kSolidHeatCapacity, "J/(kg K)", "the constant specific heat");
  hc.finish();
  read_flux(t.child("flux", "the concentrated solar flux"), case_dir, m);
  MapReader rad = t.child("radiation", "radiation exchange of the film (docs/cavity_model.md)");
  th::CavitySettings& cav = m.cavity;
  cav.enabled = rad.choice("model", "cavity", {"cavity", "open_surface"},
                           "the drum interior as a grey enclosure, or an open surface with a loss factor") == "cavity";
  // The thermal band in the film's top (docs/thermal_model.md, "The film top as a participating medium").
  m.film_top.two_flux =
      rad.choice("film_top", "surface", {"surface", "two_flux"},
                 "thermal band of the film's top: the top cell emits as a grey surface (ZBS radiation below it), or "
                 "the top film_top_depth_d emits and absorbs per cell as a participating medium (two-flux)") ==
      "two_flux";
  if (m.film_top.two_flux)
    m.film_top.depth_d =
        rad.number("film_top_depth_d", m.film_top.depth_d, Range::closed(0.5, 100.0), "particle diameters",
                   "depth below the surface of the two-flux zone (ZBS without its radiation term, "
                   "Maxwell's conduction below phi 0.4 there)");
  if (cav.enabled) {
    cav.aperture_diameter = rad.number("aperture_diameter", 0.0, Range::closed(0.0, 100.0), "m (0 = drum diameter)",
                                       "diameter of the aperture at z = L (cavity model)");
    cav.rings = static_cast<int>(rad.integer("rings", 25, 1, 2000, "axial film rings of the enclosure (cavity model)"));
    cav.wall_absorptance = rad.number("wall_absorptance", cav.wall_absorptance, Range::open_closed(0.0, 1.0), "",
                                      "solar absorptance of the back plate and front annulus (cavity model)");
    cav.wall_emissivity = rad.number("wall_emissivity", cav.wall_emissivity, Range::open_closed(0.0, 1.0), "",
                                     "thermal emissivity of the back plate and front annulus (cavity model)");
    cav.convection_correlation =
        rad.choice("convection", "correlation", {"correlation", "h_conv"},
                   "convection coefficient from the cavity correlation, or surface.h_conv (cavity model)") ==
        "correlation";
    cav.tilt_rad = rad.number("tilt_deg", 45.0, Range::closed(0.0, 90.0), "deg",
                              "receiver tilt for the convection correlation (cavity model)") *
                   3.14159265358979323846 / 180.0;
    read_front_plate(rad, cav);
    cav.spillage = rad.number("spillage", 0.0, Range::closed(0.0, 0.5), "",
                              "share of the case's aperture power that lands on the front plate's outer face "
                              "instead of entering (lost outside the cavity; cavity model)");
    // Mixed convection (docs/cavity_model.md, "Convection"): off unless given.
    cav.wind_speed = rad.number("wind_speed", 0.0, Range::closed(0.0, 50.0), "m/s",
                                "wind speed at the receiver for the forced part of the convection correlation (Ma "
                                "1993, no direction dependence; cavity model, convection: correlation)");
    cav.rotation_rad_s = rad.number("rotation_rpm", 0.0, Range::closed(0.0, 1e4), "rpm",
                                    "drum speed for the rotation-driven part of the convection correlation "
                                    "(Seghir-Ouali et al. 2006; 0: none; cavity model, convection: correlation)") *
                         2.0 * 3.14159265358979323846 / 60.0;
    cav.mixing_exponent = rad.number("mixing_exponent", 3.2, Range::closed(1.0, 10.0), "",
                                     "n of the mixing rule h = (h_natural^n + h_wind^n + h_rotation^n)^(1/n)");
    if (!cav.convection_correlation && (cav.wind_speed > 0.0 || cav.rotation_rad_s > 0.0))
      rad.fail(cav.wind_speed > 0.0 ? "wind_speed" : "rotation_rpm",
               "applies to the convection correlation (radiation.convection: correlation), not to surface.h_conv");
  }
  if (!cav.enabled && m.flux.aperture_mean > 0.0)
    t.fail("flux",
           "gives q_aperture, the flux through the cavity's aperture, but thermal.radiation.model is "
           "open_surface, which has no aperture: give flux.q_film or use the cavity model");
  if (cav.enabled && !c.film_source.from_dem() && cav.aperture_diameter > c.film.drum_diameter * (1 + 1e-9))
    rad.fail("aperture_diameter",
             "exceeds the drum diameter " + std::to_string(c.film.drum_diameter) + " m of the film");
  rad.finish();
  MapReader s = t.child("surface", "the film surface's surroundings");
  if (cav.enabled && s.has("loss_factor"))
    s.fail("loss_factor",
           "applies to the open-surface model only (thermal.radiation.model: open_surface); the "
           "cavity model computes what the cavity returns");
  m.surface.loss_factor = cav.enabled ? 1.0
                                      : s.number("loss_factor", 1.0, Range::closed(0.0, 1.0), "",
                                                 "share of the emitted radiation that is lost (open surface)");
  m.surface.T_env = s.number("T_env", 300.0, kTemperature, "K", "radiative environment seen through the aperture");
  m.surface.h_conv = s.number("h_conv", 10.0, Range::closed(0.0, 1e4), "W/(m2 K)",
                              "convection coefficient (open surface, or cavity with convection: h_conv)");
  m.surface.T_air = s.number("T_air", 300.0, kTemperature, "K", "ambient air temperature");
  s.finish();
  MapReader w = t.child("wall", "heat loss through the drum wall");
  m.wall.adiabatic = w.boolean("adiabatic", false, "no heat loss through the wall");
  if (!m.wall.adiabatic) {
    m.wall.U_w = w.number("U_w", 1.0, Range::open_closed(0.0, 1e5), "W/(m2 K)",
                          "overall wall heat-transfer coefficient (unless adiabatic)");
    m.wall.T_amb =
        w.number("T_amb", 300.0, kTemperature, "K", "ambient temperature outside the wall (unless adiabatic)");
  }
  w.finish();
  read_solver(t.child("solver", "the CVODE integrator and the steady-state search"), c);
  if (t.has("transient")) {
    MapReader tr = t.child("transient", "a transient run after the steady state (with flux or flow histories)");
    c.transient = true;
    c.transient_settings.t_end =
        tr.required_number("t_end", Range::open_closed(0.0, 1e7), "s", "simulated time of the transient");
    c.transient_settings.n_outputs =
        static_cast<int>(tr.integer("n_outputs", 121, 2, 100000, "output times, evenly spaced"));
    m.flow_time = read_time_factor(tr.child("mass_flow", "a time history multiplying the mass flow"));
    tr.finish();
  } else if (m.flux_time.kind != th::TimeFactor::Kind::constant) {
    t.fail("flux", "has a time history (flux.time) but the case has no thermal.transient section to run it");
  }
  t.finish();
  // What the thermal run checks as it sets up (grid, film, cavity), before any work.
  if (!c.film_source.from_dem()) {
    std::unique_ptr<thermal::FilmOperator> op;
    try {
      op = std::make_unique<thermal::FilmOperator>(c.film, m, c.grid);
    } catch (const std::invalid_argument& e) {
      root.fail("thermal", e.what());
    }
    // A film that, all at the top of the model's temperature range, would still absorb more
    // than it carries away and loses has no steady state the model can reach: the march
    // would only slow down toward it (docs/reliability.md).
    op->freeze_inputs(true);
    const double T_top = kTemperature.hi;
    const thermal::FilmBalance hot = op->balance(0.0, op->uniform_state(T_top).data());
    const double away = hot.carried + hot.emitted + hot.convected + hot.wall;
    if (hot.absorbed > away) {
      char why[320];
      std::snprintf(why, sizeof why,
                    "the film has no steady state below %.0f K: all at %.0f K it would absorb %.4g W but carry "
                    "away and lose only %.4g W (a flux too high for its flow %.4g kg/s and its losses)",
                    T_top, T_top, hot.absorbed, away, hot.mass_flow);
      root.fail("thermal", why);
    }
  }
}

std::string FilmSource::text() const {
  switch (kind) {
    case Kind::analytic:
      return "analytic";
    case Kind::file:
      return file;
    case Kind::dem:
      break;
  }
  return file.empty() ? "dem" : "dem: " + file;
}

std::string case_directory(const std::string& case_path) {
  const std::size_t slash = case_path.rfind('/');
  return slash == std::string::npos ? "" : case_path.substr(0, slash);
}

ThermalCase read_thermal_case(const std::string& path) {
  // The one case reader (validate's), so `thermal` accepts and refuses what `validate` does.
  return thermal_case_of(read_case_file(path));
}

ThermalCase thermal_case_of(const CaseFile& cf) {
  const std::string& path = cf.path;
  if (!cf.thermal)
    throw ConfigError(path + ": no thermal: or film: section: `centrec thermal` solves a film's energy equation");
  if (cf.thermal->film_source.from_dem())
    throw ConfigError(path +
                      ": the film comes from the case's DEM: run it with `centrec run` (or give film: {file: ...})");
  ThermalCase c = *cf.thermal;
  c.resolved_yaml = cf.resolved_yaml;
  return c;
}

}  // namespace centrec::config
