#include "config/case_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dem/material.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/packed_film.hpp"
#include "dem/scene/size_distribution.hpp"
#include "dem/sphere_mass.hpp"

namespace centrec::config {

namespace {
std::string g(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}
}  // namespace

bool Overrides::any_dem() const {
  if (any_operating_point()) return true;
  for (const auto& [key, value] : keys)
    if (key.rfind("dem.", 0) == 0 || key.rfind("receiver.", 0) == 0) return true;
  return false;
}

ReceiverCase effective_receiver(const ReceiverCase& r, const Overrides& o) {
  ReceiverCase e = r;
  if (o.speed_rpm) e.op.omega = coupling::rpm_to_rad_per_s(*o.speed_rpm);
  if (o.mass_flow) e.op.mass_flow = *o.mass_flow;
  return e;
}

DemCase effective_dem(const DemCase& dem, const ReceiverCase* receiver, const Overrides& o) {
  DemCase d = dem;
  if (receiver) {
    apply_receiver(effective_receiver(*receiver, o), d, o.any_operating_point());
  } else {
    if (o.speed_rpm) d.scene.drum.omega = coupling::rpm_to_rad_per_s(*o.speed_rpm);
    if (o.mass_flow) dem::scene::set_target_mass_flow(d.scene, *o.mass_flow);
  }
  return d;
}

std::string dem_drum_line(const DemCase& dc, bool derived) {
  const auto& s = dc.scene;
  char line[320];
  std::snprintf(line, sizeof line, "DEM drum%s: D = %.4g m (D/d %.4g), %s = %.4g m, %.6g rpm, %s %.4g g/s, dt %.3g s",
                derived ? " (derived from the receiver, receiver.dem_diameter_d)" : "", s.drum.diameter,
                s.drum.diameter / s.particle.diameter, s.slice.enabled ? "periodic slice L" : "L",
                s.slice.enabled ? s.slice.length : s.drum.length, coupling::rad_per_s_to_rpm(s.drum.omega),
                s.slice.enabled ? "slice target" : "feed", 1e3 * dem::scene::target_mass_flow(s), dem_time_step(dc));
  return line;
}

dem::TimeStepAdvice dem_time_step_advice(const DemCase& dc) {
  // As dem::Simulation::time_step_advice, over every particle the run can hold.
  const auto& s = dc.scene;
  double r = 0.5 * dem::scene::SizeSampler(s.particle, 0).min_diameter();
  if (s.rough_wall.enabled) r = std::min(r, 0.5 * s.rough_wall.sphere_diameter);
  const dem::Material& pm = s.particle.material;
  const double m = dem::sphere_mass(pm.density, r);
  const double e_pp = dem::make_pair_constants(pm, pm, s.particle_particle).E_eff;
  const double e_pw = dem::make_pair_constants(pm, s.wall_material, s.particle_wall).E_eff;
  dem::TimeStepAdvice a;
  a.max_impact_speed = s.max_impact_speed;
  a.rayleigh_time = dem::rayleigh_time(pm, r);
  a.hertz_time = std::min(dem::hertz_contact_time(0.5 * m, 0.5 * r, e_pp, s.max_impact_speed),
                          dem::hertz_contact_time(m, r, e_pw, s.max_impact_speed));
  a.stable_bound = std::min(dem::TimeStepAdvice::kRayleighBound * a.rayleigh_time,
                            dem::TimeStepAdvice::kHertzBound * a.hertz_time);
  constexpr double kDtFraction = 0.1;  // dem::SimulationConfig::dt_fraction
  a.recommended = std::min(kDtFraction * std::min(a.rayleigh_time, a.hertz_time), a.stable_bound);
  return a;
}

double dem_time_step(const DemCase& dc) {
  return dc.scene.dt > 0.0 ? dc.scene.dt : dem_time_step_advice(dc).recommended;
}

std::string time_step_statement(const dem::TimeStepAdvice& a, double dt_given) {
  if (!(dt_given > 0.0))
    return "dt = " + g(a.recommended) + " s: the recommended step (0.1 x the shorter of the Rayleigh and Hertz times)";
  return "dt = " + g(dt_given) + " s from run.dt: within the stability bound " + g(a.stable_bound) +
         " s (the smaller of 0.5 x Rayleigh time and 0.2 x Hertz time; " + g(a.hertz_time / dt_given) +
         " steps per fastest collision); the recommended " + g(a.recommended) +
         " s (0.1 x the shorter time) is the default without run.dt" +
         (dt_given > a.recommended ? "; above it the film's thickness and k_eff carry a step error, the outlet "
                                     "temperature little (docs/dem_knobs.md)"
                                   : "");
}

std::optional<CaseProblem> dem_run_problem(const DemCase& dc, bool derived) {
  const auto& s = dc.scene;
  const double d = s.particle.diameter, R = 0.5 * s.drum.diameter, L = s.drum.length;
  const std::string drum_key = derived ? "receiver.dem_diameter_d" : "dem.drum.diameter";
  const std::string drum_is = derived ? "the DEM drum derived from receiver.dem_diameter_d" : "the drum diameter";
  if (!(R > 10.0 * d))
    return CaseProblem{drum_key, drum_is + " = " + g(s.drum.diameter) + " m must exceed 20 particle diameters (" +
                                     g(20.0 * d) + " m)"};
  if (!(L > d))
    return CaseProblem{derived ? drum_key : "dem.drum.length",
                       "the drum length " + g(L) + " m must exceed one particle diameter (" + g(d) + " m)"};
  if (!std::isfinite(s.drum.omega) || s.drum.omega == 0.0 || std::fabs(coupling::rad_per_s_to_rpm(s.drum.omega)) > 1e5)
    return CaseProblem{derived ? "receiver.speed_rpm" : "dem.drum.speed_rpm",
                       "the drum speed " + g(coupling::rad_per_s_to_rpm(s.drum.omega)) +
                           " rpm must be non-zero and at most 1e5 rpm (turns count the run's sampling and flow windows)"};
  if (s.slice.enabled && s.drum.lip_height > 0.0)
    return CaseProblem{"dem.drum.outlet_lip_height_d", "a periodic slice has no outlet, so no lip (set it to 0)"};
  const bool fed = s.feeder.enabled && !s.slice.enabled;
  if (fed) {
    const auto& f = s.feeder;
    if (!(f.radial_offset > 0.0 && f.radial_offset < R))
      return CaseProblem{"dem.feeder.radial_offset_d", "the feeder centre " + g(f.radial_offset) +
                                                           " m inside the wall lies outside the drum radius " + g(R) + " m"};
    // The region's particles touch rc +- radial_height / 2 (dem/scene/feeder.cpp): inside the
    // wall's inner surface (the rough wall's spheres included), short of the axis, and an arc
    // that does not wrap onto itself.
    const double rc = R - f.radial_offset, inner = R - (s.rough_wall.enabled ? s.rough_wall.sphere_diameter : 0.0);
    if (rc + 0.5 * f.radial_height > inner)
      return CaseProblem{"dem.feeder.radial_height_d",
                         "the feeder region reaches " + g(rc + 0.5 * f.radial_height) +
                             " m from the axis, into the wall (its inside, rough wall included, is at " + g(inner) +
                             " m): lower radial_height_d or raise radial_offset_d"};
    if (rc - 0.5 * f.radial_height < 0.0)
      return CaseProblem{"dem.feeder.radial_height_d", "the feeder region (" + g(f.radial_height) +
                                                           " m high about " + g(rc) +
                                                           " m from the axis) crosses the drum's axis"};
    if (f.arc_width > 2.0 * M_PI * rc)
      return CaseProblem{"dem.feeder.arc_width_d", "the arc " + g(f.arc_width) +
                                                       " m is longer than the circumference at the feeder's radius (" +
                                                       g(2.0 * M_PI * rc) + " m)"};
    if (f.axial_start + f.axial_length > L)
      return CaseProblem{"dem.feeder.axial_length_d", "the feeder region (axial_start + axial_length = " +
                                                          g(f.axial_start + f.axial_length) +
                                                          " m) extends past the drum length " + g(L) + " m"};
    // The most the region can take per batch: filled at the densest packing of spheres.
    const double region = f.axial_length * f.radial_height * f.arc_width;
    const double capacity = 0.74 * region * s.particle.material.density / f.interval;
    // A feed below one particle per drum turn forms no film in any run length the step
    // count allows (1e-300 kg/s is a typo, not an operating point).
    const double particle = dem::sphere_mass(s.particle.material.density, 0.5 * d);
    const double per_turn = particle / dem::scene::turn_period(s);
    if (f.mass_flow > 0.0 && f.mass_flow < per_turn)
      return CaseProblem{derived ? "receiver.mass_flow" : "dem.feeder.mass_flow",
                         "the feed " + g(f.mass_flow) + " kg/s delivers less than one particle (" + g(particle) +
                             " kg) per drum turn (" + g(dem::scene::turn_period(s)) + " s): no film forms; give at least " +
                             g(per_turn) + " kg/s, or 0 for no feed"};
    if (f.mass_flow > capacity)
      return CaseProblem{derived ? "receiver.mass_flow" : "dem.feeder.mass_flow",
                         "the feed " + g(f.mass_flow) + " kg/s exceeds what the feeder region can insert (" +
                             g(capacity) + " kg/s: its volume " + g(region) + " m^3 filled densely every " +
                             g(f.interval) + " s); enlarge the region or lower the flow"};
  }
  if (s.initial_film.particles > 0) {
    const dem::scene::LooseFilmRegion film = dem::scene::loose_film_region(s);
    if (film.periodic && (s.initial_film.axial_from > 0.0 || s.initial_film.axial_to > 0.0))
      return CaseProblem{s.initial_film.axial_from > 0.0 ? "dem.initial_film.axial_from" : "dem.initial_film.axial_to",
                         "a slice's film fills its whole period; axial_from and axial_to place a drum's film"};
    if (!film.periodic && !(film.z0 < L))
      return CaseProblem{"dem.initial_film.axial_from",
                         "the film starts at " + g(film.z0) + " m, past the drum's end (" + g(L) + " m)"};
    if (!film.periodic && !(film.z1 <= L))
      return CaseProblem{"dem.initial_film.axial_to",
                         "the film ends at " + g(film.z1) + " m, past the drum's end (" + g(L) + " m)"};
    if (!film.periodic && !(film.z0 < film.z1))
      return CaseProblem{"dem.initial_film.axial_to", "the film's end " + g(film.z1) + " m is not past its start " +
                                                          g(film.z0) + " m (dem.initial_film.axial_from)"};
    const std::size_t count = static_cast<std::size_t>(s.initial_film.particles);
    const std::size_t fits = dem::scene::loose_film_capacity(s, count);
    if (count > fits)
      return CaseProblem{"dem.initial_film.particles",
                         std::to_string(count) + " particles do not fit in the drum (its starting lattice holds at most " +
                             std::to_string(fits) + " between z = " + g(film.z0) + " and " + g(film.z1) + " m)"};
  }
  const auto& sp = dc.sampling.sampler;
  const double bins = static_cast<double>(sp.axial_sections) * sp.tangential_bins * sp.bins;
  if (dc.sampling.turns > 0.0 && bins > 1e7)
    return CaseProblem{"dem.sampling.bins", "axial_sections x tangential_bins x bins = " + g(bins) +
                                                " sampling bins per field, more than 1e7 (" + g(bins * 8e-9) +
                                                " GB each): fewer sections, bins or tangential bins"};
  const dem::TimeStepAdvice a = dem_time_step_advice(dc);
  if (s.dt > a.stable_bound)
    return CaseProblem{"dem.run.dt", "dt = " + g(s.dt) + " s exceeds the stability bound " + g(a.stable_bound) +
                                         " s (" + g(dem::TimeStepAdvice::kRayleighBound) + " x Rayleigh time " +
                                         g(a.rayleigh_time) + " s, " + g(dem::TimeStepAdvice::kHertzBound) +
                                         " x Hertz contact time " + g(a.hertz_time) + " s at " +
                                         g(a.max_impact_speed) + " m/s); use dt <= " + g(a.stable_bound) +
                                         " s (recommended " + g(a.recommended) + " s)"};
  const double dt = s.dt > 0.0 ? s.dt : a.recommended;
  if (dc.run.duration < dt)
    return CaseProblem{"dem.run.duration", "run.duration = " + g(dc.run.duration) +
                                               " s is shorter than one time step (dt = " + g(dt) +
                                               " s): the spin-up would run no step; give at least a few drum turns"};
  // The longest run: the spin-up with its longest extension, then the sampled turns.
  const double extension = dc.run.extension_cap();
  const double simulated = dc.run.duration + extension + dc.sampling.turns * dem::scene::turn_period(s);
  const double steps = simulated / dt;
  if (!(steps <= kMaxSteps))
    return CaseProblem{extension > dc.run.duration ? "dem.run.max_extension"
                       : s.dt > 0.0                  ? "dem.run.dt"
                                                     : "dem.run.duration",
                       "the run would take up to " + g(steps) + " time steps (" + g(simulated) +
                           " s simulated at dt = " + g(dt) + " s, the spin-up's longest extension included), more than " +
                           g(kMaxSteps) + ": it cannot finish; check run.dt, run.duration and run.max_extension"};
  return std::nullopt;
}

std::optional<CaseProblem> coupled_run_problem(const DemCase& dem, const ThermalCase& thermal,
                                               const ReceiverCase* receiver) {
  const auto& m = thermal.model.material;
  const double d = dem.scene.particle.diameter, rho = dem.scene.particle.material.density;
  if (std::abs(m.d / d - 1.0) > 1e-9)
    return CaseProblem{"thermal.material.d", "the thermal particles (d = " + g(m.d) +
                                                 " m) differ from the DEM's (dem.particles.diameter = " + g(d) +
                                                 " m): make them equal"};
  if (std::abs(m.rho_s / rho - 1.0) > 1e-9)
    return CaseProblem{"thermal.material.rho_s", "the thermal particles (rho_s = " + g(m.rho_s) +
                                                     " kg/m3) differ from the DEM's (dem.particles.density = " +
                                                     g(rho) + " kg/m3): make them equal"};
  const double D = receiver ? receiver->op.diameter : dem.scene.drum.diameter;
  const auto& cav = thermal.model.cavity;
  if (cav.enabled && cav.aperture_diameter > D * (1 + 1e-9))
    return CaseProblem{"thermal.radiation.aperture_diameter", "exceeds the diameter " + g(D) + " m of the " +
                                                                  (receiver ? "receiver" : "DEM drum")};
  if (!(dem.sampling.turns > 0.0))
    return CaseProblem{"dem.sampling.turns", "must be > 0 in a coupled case: the film comes from the DEM's sampled turns"};
  return std::nullopt;
}

std::optional<CaseProblem> sweep_problem(const DemCase& dem, const ReceiverCase* receiver, const SweepSpec& sweep) {
  const bool derived = receiver && receiver->dem_diameter_d > 0.0;
  for (const double rpm : sweep.speed_rpm)
    for (const double mdot : sweep.mass_flow) {
      Overrides o;
      o.speed_rpm = rpm;
      o.mass_flow = mdot;
      const std::string point = "the point " + g(rpm) + " rpm x " + g(mdot) + " kg/s";
      std::optional<CaseProblem> p;
      try {
        p = dem_run_problem(effective_dem(dem, receiver, o), derived);
      } catch (const std::invalid_argument& e) {
        p = CaseProblem{"receiver", e.what()};
      }
      if (!p) continue;
      // Name the swept value the refusal concerns: a speed, a flow, or the point.
      const bool speed = p->key.find("speed_rpm") != std::string::npos || p->key.find("run.") != std::string::npos;
      const bool flow = p->key.find("mass_flow") != std::string::npos;
      return CaseProblem{speed ? "sweep.speed_rpm" : flow ? "sweep.mass_flow" : "sweep",
                         point + " cannot run (" + p->key + "): " + p->message};
    }
  return std::nullopt;
}

}  // namespace centrec::config
