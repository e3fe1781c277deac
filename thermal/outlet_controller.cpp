#include "outlet_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace centrec::thermal {

namespace {
// Restores the operator's time factors however the run ends (the controller and the step test
// replace them).
class RestoreTimeFactors {
 public:
  explicit RestoreTimeFactors(FilmOperator& op) : op_(op), flux_(op.model().flux_time), flow_(op.model().flow_time) {}
  ~RestoreTimeFactors() {
    op_.set_flux_time(flux_);
    op_.set_flow_time(flow_);
  }
  RestoreTimeFactors(const RestoreTimeFactors&) = delete;
  RestoreTimeFactors& operator=(const RestoreTimeFactors&) = delete;

 private:
  FilmOperator& op_;
  TimeFactor flux_, flow_;
};

TimeFactor lag(double from, double to, double t_start, double tau) {
  TimeFactor f;
  f.kind = TimeFactor::Kind::lag;
  f.from = from;
  f.level = to;
  f.t_start = t_start;
  f.tau = tau;
  return f;
}

void check(const ControlledTransientSettings& s) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("controlled transient: " + what); };
  if (!(s.t_end > 0.0)) fail("t_end must be > 0 s");
  if (!(s.dt_control > 0.0)) fail("dt_control must be > 0 s");
  if (!(s.tau_film >= 0.0)) fail("tau_film must be >= 0 s");
  if (!(s.m_min > 0.0 && s.m_max >= s.m_min)) fail("the flow limits need 0 < m_min <= m_max");
  if (!s.control && !(s.m_fixed > 0.0)) fail("m_fixed must be > 0");
  if (s.control && !std::isnan(s.kp) && !std::isnan(s.ki) && !(s.kp >= 0.0 && s.ki >= 0.0))
    fail("kp and ki must be >= 0 (the action is fixed: too hot -> more flow)");
}
}  // namespace

ControlledTransientResult run_controlled_transient(FilmOperator& op, const std::vector<double>& y0,
                                                   const ControlledTransientSettings& s) {
  check(s);
  const TimeFactor& flow0 = op.model().flow_time;
  if (!(flow0.kind == TimeFactor::Kind::constant && flow0.level == 1.0))
    throw std::invalid_argument(
        "controlled transient: the model's mass-flow time factor must be constant 1 (the "
        "controller sets the mass flow)");
  ControlledTransientResult r;
  r.T_set = std::isnan(s.T_set) ? op.balance(0.0, y0.data()).T_out : s.T_set;
  r.kp = s.kp;
  r.ki = s.ki;
  if (s.control && (std::isnan(s.kp) || std::isnan(s.ki))) {
    const OutletTuning tuning = tune_outlet_controller(op, y0, s);
    r.kp = tuning.gains.kp;
    r.ki = tuning.gains.ki;
  }
  RestoreTimeFactors restore(op);
  op.freeze_inputs(false);
  // Kinks of the flux inside (0, t_end): restart points, as in run_transient.
  std::vector<double> kinks;
  for (const double b : op.model().flux_time.breakpoints())
    if (b > 0.0 && b < s.t_end) kinks.push_back(b);
  double m_cmd = s.control ? 1.0 : s.m_fixed;
  double integral = 0.0;  // of e over time, K s
  // The film the plant runs on: op, or the one film_at gave for the flow factor m_film; its
  // own flow factor is the applied one over m_film. The lag in absolute flow factors.
  FilmOperator* film = &op;
  std::unique_ptr<FilmOperator> owned;
  double m_film = 1.0, lag_from = 1.0, lag_to = m_cmd, lag_t0 = 0.0;
  auto apply_lag = [&] { film->set_flow_time(lag(lag_from / m_film, lag_to / m_film, lag_t0, s.tau_film)); };
  apply_lag();
  std::vector<double> y = y0;
  auto cv = std::make_unique<CvodeIntegrator>(*film, s.integrator, 0.0, y);
  SolverStats earlier;  // of the integrators of earlier films
  std::size_t next_kink = 0;
  // Control instants k dt_control, the last one t_end (a shorter interval if it is no multiple).
  const long n = std::max(1L, static_cast<long>(std::ceil(s.t_end / s.dt_control - 1e-9)));
  for (long k = 0; k <= n; ++k) {
    const double t = k == n ? s.t_end : k * s.dt_control;
    while (next_kink < kinks.size() && kinks[next_kink] <= t) {
      const double tk = kinks[next_kink++];
      if (tk > cv->time()) {
        cv->advance(tk, y);
        cv->reinit(tk, y);
      }
    }
    cv->advance(t, y);
    const FilmBalance b = film->balance(t, y.data());
    const double m = m_film * film->model().flow_time.at(t);
    if (s.control) {
      const double e = b.T_out - r.T_set;
      const double trial = integral + e * s.dt_control;
      const double eta = s.feedforward_efficiency;
      const double base = std::isnan(eta) ? 1.0 : (op.model().flux_time.at(t) - (1.0 - eta)) / eta;
      const double u = base + r.kp * e + r.ki * trial;
      // Conditional integration: no integration that drives a saturated command further out.
      const bool winding = (u > s.m_max && e > 0.0) || (u < s.m_min && e < 0.0);
      if (!winding) integral = trial;
      m_cmd = std::clamp(base + r.kp * e + r.ki * integral, s.m_min, s.m_max);
      lag_from = m, lag_to = m_cmd, lag_t0 = t;
    }
    ControlSample c;
    c.t = t;
    c.flux_factor = op.model().flux_time.at(t);
    c.m_cmd = m_cmd;
    c.m = m;
    c.mass_flow = b.mass_flow;
    c.T_out = b.T_out;
    const ThermalFields f = film->fields(t, y.data());
    c.T_surface_max = *std::max_element(f.T_surface.begin(), f.T_surface.end());
    c.T_max = *std::max_element(y.begin(), y.end());
    c.efficiency = b.efficiency;
    r.samples.push_back(c);
    // The film of the flow applied now, its temperatures kept cell by cell.
    if (s.film_at && k < n && std::abs(m / m_film - 1.0) > s.refilm_step) {
      std::unique_ptr<FilmOperator> next = s.film_at(m);
      if (!next || next->size() != film->size())
        throw std::invalid_argument("controlled transient: film_at gave no film, or one on another grid");
      next->set_flux_time(op.model().flux_time);
      next->freeze_inputs(false);
      const double before = film->stored_enthalpy(y.data()), after = next->stored_enthalpy(y.data());
      r.refilm_enthalpy += after - before;
      r.refilm_enthalpy_abs += std::abs(after - before);
      ++r.refilms;
      earlier += cv->stats();
      cv.reset();
      owned = std::move(next);
      film = owned.get();
      m_film = m;
      apply_lag();
      cv = std::make_unique<CvodeIntegrator>(*film, s.integrator, t, y);
    } else if (s.control) {
      apply_lag();
      cv->reinit(t, y);  // u's slope changes here
    }
  }
  r.y_end = y;
  r.stats = earlier;
  r.stats += cv->stats();
  return r;
}

FopdtFit fit_first_order_dead_time(const std::vector<double>& t, const std::vector<double>& y) {
  if (t.size() != y.size() || t.size() < 3) throw std::invalid_argument("FOPDT fit: needs >= 3 (t, y) samples");
  FopdtFit f;
  f.change = y.back() - y.front();
  if (!(std::abs(f.change) > 0.0)) throw std::invalid_argument("FOPDT fit: the response does not change");
  // First time the normalised response reaches `level`, linear between samples.
  auto crossing = [&](double level) {
    for (std::size_t k = 1; k < t.size(); ++k) {
      const double a = (y[k - 1] - y.front()) / f.change, b = (y[k] - y.front()) / f.change;
      if (b >= level) return t[k - 1] + (level - a) / (b - a) * (t[k] - t[k - 1]);
    }
    throw std::invalid_argument("FOPDT fit: the response never reaches 63.2 % of its change");
  };
  // 1 - e^(-1/3) and 1 - e^(-1): a FOPDT response reaches them at theta + tau_1 / 3 and theta + tau_1.
  f.t28 = crossing(1.0 - std::exp(-1.0 / 3.0)) - t.front();
  f.t63 = crossing(1.0 - std::exp(-1.0)) - t.front();
  f.time_constant = 1.5 * (f.t63 - f.t28);
  f.dead_time = std::max(0.0, f.t63 - f.time_constant);
  if (!(f.time_constant > 0.0)) throw std::invalid_argument("FOPDT fit: no time constant (a step in the output)");
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double tau = t[k] - t.front() - f.dead_time;
    const double model = tau > 0.0 ? 1.0 - std::exp(-tau / f.time_constant) : 0.0;
    f.max_misfit = std::max(f.max_misfit, std::abs((y[k] - y.front()) / f.change - model));
  }
  return f;
}

PiGains simc_pi_gains(double K, double dead_time, double time_constant, double dt_control, double tau_c) {
  if (!(std::abs(K) > 0.0) || !(time_constant > 0.0) || !(dead_time >= 0.0) || !(dt_control > 0.0))
    throw std::invalid_argument("SIMC: needs a process gain != 0, time constant > 0, dead time >= 0, dt > 0");
  PiGains g;
  g.theta_eff = dead_time + 0.5 * dt_control;  // the hold delays the action by half an interval on average
  g.tau_c = std::isnan(tau_c) ? g.theta_eff : tau_c;
  g.kp = time_constant / (std::abs(K) * (g.tau_c + g.theta_eff));
  g.tau_i = std::min(time_constant, 4.0 * (g.tau_c + g.theta_eff));
  g.ki = g.kp / g.tau_i;
  return g;
}

OutletTuning tune_outlet_controller(FilmOperator& op, const std::vector<double>& y0,
                                    const ControlledTransientSettings& s, double step) {
  if (!(step != 0.0 && 1.0 + step > 0.0)) throw std::invalid_argument("tuning: the flow step must be != 0 and > -1");
  RestoreTimeFactors restore(op);
  TimeFactor held;  // the flux at its operating point
  held.level = op.model().flux_time.at(0.0);
  op.set_flux_time(held);
  ControlledTransientSettings open = s;
  open.control = false;
  open.m_fixed = 1.0 + step;
  open.t_end = 8.0 * (op.time_scale() + s.tau_film);
  open.dt_control = open.t_end / 400.0;
  const ControlledTransientResult r = run_controlled_transient(op, y0, open);
  std::vector<double> t, T;
  for (const ControlSample& c : r.samples) {
    t.push_back(c.t);
    T.push_back(c.T_out);
  }
  OutletTuning u;
  u.step = step;
  u.T_out_start = T.front();
  u.T_out_end = T.back();
  u.fit = fit_first_order_dead_time(t, T);
  u.gain = u.fit.change / step;
  if (!(u.gain < 0.0))
    throw std::invalid_argument("tuning: T_out does not fall when the mass flow rises (dT_out/dm = " +
                                std::to_string(u.gain) + " K); the controller's action would be wrong");
  u.gains = simc_pi_gains(u.gain, u.fit.dead_time, u.fit.time_constant, s.dt_control);
  return u;
}

}  // namespace centrec::thermal
