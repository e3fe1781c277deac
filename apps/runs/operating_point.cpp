#include "operating_point.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "coupling/film_mass_flow.hpp"
#include "runs/thermal_case_run.hpp"

namespace centrec::runs {

SurrogateThermal::SurrogateThermal(config::ThermalCase base, const coupling::FilmSurrogate& surrogate,
                                   double receiver_diameter)
    : base_(std::move(base)), surrogate_(surrogate), receiver_diameter_(receiver_diameter) {
  base_.transient = false;
}

SurrogateThermal::Answer SurrogateThermal::at(double speed_rpm, double mass_flow) const {
  return on_film(surrogate_.film_at(speed_rpm, mass_flow), mass_flow);
}

config::ThermalCase SurrogateThermal::case_at(double speed_rpm, double mass_flow) const {
  return on_film_case(surrogate_.film_at(speed_rpm, mass_flow), mass_flow, nullptr);
}

config::ThermalCase SurrogateThermal::case_at(double speed_rpm, double mass_flow, double film_mass_flow) const {
  return on_film_case(surrogate_.film_at(speed_rpm, film_mass_flow), mass_flow, nullptr);
}

config::ThermalCase SurrogateThermal::on_film_case(thermal::FilmField film, double mass_flow,
                                                   double* velocity_factor) const {
  config::ThermalCase c = base_;
  c.film = std::move(film);
  c.film.drum_diameter = receiver_diameter_;
  const coupling::ImposedFlow imposed = coupling::impose_mass_flow(c.film, c.model.material.rho_s, mass_flow);
  if (velocity_factor) *velocity_factor = imposed.factor;
  return c;
}

SurrogateThermal::Answer SurrogateThermal::on_film(thermal::FilmField film, double mass_flow) const {
  Answer a;
  const config::ThermalCase c = on_film_case(std::move(film), mass_flow, &a.velocity_factor);
  const auto t0 = std::chrono::steady_clock::now();
  const ThermalRun r = run_thermal_case(c, false);
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  a.T_out = r.balance.T_out;
  a.efficiency = r.balance.efficiency;
  for (double T : r.fields.T_surface) a.T_surface_max = std::max(a.T_surface_max, T);
  for (double T : r.steady.y) a.T_max = std::max(a.T_max, T);
  a.thickness_d = c.film.t[0] / c.film.particle_diameter;
  return a;
}

namespace {

// T_out(mdot) falls with the mass flow: regula falsi (Illinois) in ln(mdot) on [lo, hi].
void solve_at_speed(const SurrogateThermal& th, double target, double lo, double hi, OperatingCandidate& c) {
  auto T = [&](double mdot) {
    ++c.solves;
    return th.at(c.speed_rpm, mdot);
  };
  SurrogateThermal::Answer a_lo = T(lo), a_hi = T(hi);
  char buf[200];
  if (target > a_lo.T_out || target < a_hi.T_out) {
    std::snprintf(buf, sizeof buf, "T_out spans %.2f-%.2f K over the window's %.4g-%.4g kg/s at this speed",
                  a_hi.T_out, a_lo.T_out, lo, hi);
    c.why_not = buf;
    return;
  }
  double x0 = std::log(lo), x1 = std::log(hi), f0 = a_lo.T_out - target, f1 = a_hi.T_out - target;
  int side = 0;
  for (int it = 0; it < 40; ++it) {
    const double x = x1 - f1 * (x1 - x0) / (f1 - f0);
    const SurrogateThermal::Answer a = T(std::exp(x));
    const double f = a.T_out - target;
    if (std::abs(f) < 0.02) {
      c.found = true;
      c.mass_flow = std::exp(x);
      c.answer = a;
      return;
    }
    if ((f > 0) == (f1 > 0)) {  // replaces x1: the Illinois halving of the end kept twice
      x1 = x, f1 = f;
      if (side == 1) f0 *= 0.5;
      side = 1;
    } else {
      x0 = x, f0 = f;
      if (side == -1) f1 *= 0.5;
      side = -1;
    }
  }
  c.why_not = "no convergence within 40 solves";
}

}  // namespace

OperatingAnswer find_operating_point(const OperatingMap& m, const SurrogateThermal& th, double target_T_out,
                                     int n_speeds, const OperatingCriterion& criterion) {
  if (n_speeds < 1) throw std::invalid_argument("operating point: at least one speed");
  OperatingAnswer out;
  out.target_T_out = target_T_out;
  char crit[200];
  std::snprintf(crit, sizeof crit, "highest efficiency at T_out = %.2f K inside the stable window", target_T_out);
  out.criterion = crit;
  if (criterion.min_thickness_d > 0) {
    std::snprintf(crit, sizeof crit, ", film >= %.3g d", criterion.min_thickness_d);
    out.criterion += crit;
  }
  if (criterion.min_margin_rpm > 0) {
    std::snprintf(crit, sizeof crit, ", >= %.3g rpm from the window's speed edges", criterion.min_margin_rpm);
    out.criterion += crit;
  }
  // The window's speed range: speeds with a usable mass-flow span.
  double v_lo = 0.0, v_hi = 0.0;
  bool any = false;
  for (std::size_t i = 0; i + 1 < m.speeds.size(); ++i) {
    const double mid = 0.5 * (m.speeds[i] + m.speeds[i + 1]);
    const auto span = m.flow_span(mid);
    if (span.second <= span.first) continue;
    if (!any) v_lo = m.speeds[i];
    v_hi = m.speeds[i + 1];
    any = true;
  }
  if (!any) {
    // Not an error of the inputs but the map's answer: the caller reports it as such.
    out.why_none = "the map has no stable cell (no 2 x 2 block of usable points)";
    return out;
  }
  const double R = criterion.min_margin_rpm;
  if (v_hi - v_lo < 2.0 * R) {
    char why[200];
    std::snprintf(why, sizeof why, "the window's speeds (%.4g-%.4g rpm) leave no speed %.3g rpm from both edges",
                  v_lo, v_hi, R);
    out.why_none = why;
    return out;
  }
  v_lo += R;
  v_hi -= R;
  for (int k = 0; k < n_speeds; ++k) {
    OperatingCandidate c;
    c.speed_rpm = n_speeds == 1 ? 0.5 * (v_lo + v_hi) : v_lo + (v_hi - v_lo) * k / (n_speeds - 1);
    const auto span = m.flow_span(c.speed_rpm);
    if (span.second <= span.first) {
      c.why_not = "no stable mass-flow span at this speed";
    } else {
      solve_at_speed(th, target_T_out, span.first, span.second, c);
      if (c.found) c.margin = m.margin(c.speed_rpm, c.mass_flow);
      if (c.found && c.answer.thickness_d < criterion.min_thickness_d) {
        c.found = false;
        c.why_not = "film " + std::to_string(c.answer.thickness_d) + " d thinner than the minimum";
      }
      // The window may be narrower at this mass flow than over the speeds tried.
      if (c.found && std::min(c.margin.speed_below, c.margin.speed_above) < R * (1.0 - 1e-9)) {
        c.found = false;
        char why[160];
        std::snprintf(why, sizeof why, "%.4g kg/s lies %.3g / %.3g rpm from the window's speed edges, less than %.3g",
                      c.mass_flow, c.margin.speed_below, c.margin.speed_above, R);
        c.why_not = why;
      }
    }
    out.candidates.push_back(c);
    if (c.found && (out.best < 0 || c.answer.efficiency > out.candidates[out.best].answer.efficiency))
      out.best = static_cast<int>(out.candidates.size()) - 1;
  }
  return out;
}

CheckRefinement refine_by_full_runs(double target, double mass_flow, double surrogate_slope,
                                    std::pair<double, double> span, int max_runs, double tolerance,
                                    const std::function<double(double)>& full_T_out) {
  if (max_runs < 1) throw std::invalid_argument("check: at least one full run");
  CheckRefinement r;
  double m = mass_flow;
  char why[200];
  for (int k = 0; k < max_runs; ++k) {
    r.runs.push_back({m, full_T_out(m)});
    const FullRun& last = r.runs.back();
    if (std::abs(last.T_out - target) <= tolerance) return r;
    if (k + 1 == max_runs) break;
    double slope = surrogate_slope;  // dT_out / dmdot, K per kg/s
    if (r.runs.size() >= 2) {
      const FullRun& prev = r.runs[r.runs.size() - 2];
      if (last.mass_flow != prev.mass_flow) slope = (last.T_out - prev.T_out) / (last.mass_flow - prev.mass_flow);
    }
    if (!(slope < 0.0)) {
      std::snprintf(why, sizeof why, "the slope dT_out/dmdot is %.4g K per kg/s, not negative: no secant step", slope);
      r.why_stopped = why;
      return r;
    }
    m = last.mass_flow + (target - last.T_out) / slope;
    if (m < span.first || m > span.second) {
      std::snprintf(why, sizeof why, "the secant step asks %.5g kg/s, outside the window's %.5g-%.5g kg/s at this speed",
                    m, span.first, span.second);
      r.why_stopped = why;
      return r;
    }
  }
  std::snprintf(why, sizeof why, "%d full run(s) made (--check-runs), the last %+.2f K from the target", max_runs,
                r.runs.back().T_out - target);
  r.why_stopped = why;
  return r;
}

}  // namespace centrec::runs

namespace centrec::runs {

CloudResponse cloud_response(const SurrogateThermal& th, double speed_rpm, double mass_flow,
                             const thermal::TimeFactor& flux, thermal::ControlledTransientSettings s,
                             std::pair<double, double> film_flows) {
  ThermalRun r = run_thermal_case(th.case_at(speed_rpm, mass_flow), false);
  if (film_flows.first < film_flows.second)
    s.film_at = [&th, speed_rpm, mass_flow, film_flows](double m) {
      const double carried = m * mass_flow;
      const config::ThermalCase c =
          th.case_at(speed_rpm, carried, std::clamp(carried, film_flows.first, film_flows.second));
      return std::make_unique<thermal::FilmOperator>(c.film, c.model, c.grid);
    };
  thermal::FilmOperator& op = *r.op;
  const std::vector<double>& y0 = r.steady.y;
  CloudResponse out;
  out.residence_time = op.time_scale();
  out.efficiency = r.balance.efficiency;
  out.film_enthalpy = op.stored_enthalpy(y0.data());
  out.film_follows = static_cast<bool>(s.film_at);
  if (std::isnan(s.tau_film)) s.tau_film = kFilmResponseOverResidence * out.residence_time;
  out.film_response = s.tau_film;
  // The gains from the step response at the steady flux; then the cloud.
  out.tuning = thermal::tune_outlet_controller(op, y0, s);
  s.kp = out.tuning.gains.kp;
  s.ki = out.tuning.gains.ki;
  op.set_flux_time(flux);
  s.control = false;
  out.fixed = thermal::run_controlled_transient(op, y0, s);
  s.control = true;
  out.pi = thermal::run_controlled_transient(op, y0, s);
  s.feedforward_efficiency = out.efficiency;
  out.feedforward = thermal::run_controlled_transient(op, y0, s);
  return out;
}

}  // namespace centrec::runs
