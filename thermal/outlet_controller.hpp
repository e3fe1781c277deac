#pragma once
// The outlet temperature held by the particle mass flow, as a real receiver is run through a
// passing cloud (docs/thermal_model.md, "Solvers": transients; the film and its time factors).
//
// Plant: the film transient of thermal/transient_run.hpp with the mass flow a time factor on u
// (FilmModel::flow_time). The applied flow factor m (relative to the initial mass flow) scales
// every mass flux of the film, axial and wall-normal, with the film thickness, the solid
// fraction and the dispersion fixed. Limit: a fed drum's film thickens and speeds up together
// when its feed rises (its holdup grows less than the flow), so the residence time here falls as
// 1/m where the real film's falls more slowly, and the conduction and surface temperature of a
// thicker film are not represented. Valid near the DEM's operating point (m near 1); far from it
// T_out(m) and the tuned gains are approximations.
//
// With `film_at` (the film surrogate of an operating map, docs/operating.md), the film follows
// its flow instead: whenever the applied flow factor has moved by more than refilm_step from
// the film's, the plant takes the film the surrogate gives at that flow (its thickness,
// velocity, solid fraction and dispersion; the residence time then falls as the real film's
// does), with the cell temperatures kept at the same (z, xi = eta / t). That is not
// conservative: a thicker film holds more mass at the temperatures of the old one, where the
// real film's added mass enters at T_in. The enthalpy this creates or destroys (stored_enthalpy
// before and after, summed) is reported with the result, so the forcing is measured.
//
// The film follows the command with a first-order lag: m' = (m_cmd - m) / tau_film, tau_film the
// fed drum's holdup response time (a parameter here: a film whose holdup H goes as mdot^a answers
// a feed step with tau = a H / mdot; a fed drum's feed step measured a = 0.18, its standing base
// not moving, so tau = 0.18-0.20 of the residence time with no measurable dead time,
// docs/operating.md "The film's response time, measured"). Within a control interval m_cmd is constant, so the
// lag is applied exactly as m = m_cmd + (m_k - m_cmd) exp(-(t - t_k) / tau_film) (a `lag`
// TimeFactor): no O(dt / tau_film) error of a piecewise-constant m, and no jump in u every
// interval; u stays continuous, kinked at the control instants, where the integrator restarts.
//
// Controller: a sampled PI on e = T_out - T_set (mixing-cup T_out read every dt_control):
//   I_k = I_(k-1) + e_k dt_control,  m_cmd = 1 + kp e_k + ki I_k,  clamped to [m_min, m_max],
// too hot -> more flow (kp, ki > 0). Anti-windup by conditional integration: I is not updated
// when the unclamped command is beyond a limit and e pushes it further out, so the integral does
// not grow while the flow is saturated (a deep cloud at m_min) and the loop recovers without an
// overshoot of its stored error.
//
// Feedforward (feedforward_efficiency = eta, the steady efficiency at the set point): a plant
// measures its flux (DNI), so the flow the energy balance needs can be commanded before T_out
// moves. At the set point the film's losses hang on its temperatures, not on the flux, so they
// stay (1 - eta) P0 when the aperture power falls to f P0 and the carried power is
// f P0 - (1 - eta) P0 = eta m P0 at the same temperature rise: m_ff = (f - (1 - eta)) / eta.
// The PI adds to it: m_cmd = m_ff(f(t_k)) + kp e_k + ki I_k (clamped as above).
//
// Tuning (tune_outlet_controller): the plant's step response is measured on the given operator
// (open loop, the commanded factor stepped 1 -> 1 + step at t = 0 through the lag, the flux held
// at its t = 0 value) and fitted by first order plus dead time, K e^(-theta s) / (tau_1 s + 1),
// with the two-point rule: t28 and t63, the times of 28.3 % and 63.2 % of the change
// (1 - e^(-1/3) and 1 - e^(-1)),
//   tau_1 = 1.5 (t63 - t28),  theta = t63 - tau_1   (exact for a FOPDT response)
// (Smith 1972; Seborg, Edgar & Mellichamp, Process Dynamics and Control, 7.2). The gains follow
// the SIMC rule (Skogestad 2003, J. Process Control 13, 291) with the hold's half interval
// added to the delay, theta_eff = theta + dt_control / 2, and the closed-loop time constant
// tau_c = theta_eff (SIMC's "tight but robust" choice: gain margin ~3, phase margin ~47 deg):
//   kp = tau_1 / (|K| (tau_c + theta_eff)),  tau_I = min(tau_1, 4 (tau_c + theta_eff)),  ki = kp / tau_I.
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "cvode_integrator.hpp"
#include "film_operator.hpp"

namespace centrec::thermal {

struct ControlledTransientSettings {
  double t_end = 200.0;     // s
  double dt_control = 1.0;  // s: the controller's sample and hold, and the output interval
  bool control = true;      // false: no controller, the commanded flow factor held at m_fixed
  double m_fixed = 1.0;     // commanded flow factor without control from t = 0 (1: the initial flow)
  double T_set = std::numeric_limits<double>::quiet_NaN();  // K; NaN: T_out of y0
  // PI gains; NaN (either): both from tune_outlet_controller on this operator and y0.
  double kp = std::numeric_limits<double>::quiet_NaN();  // 1/K
  double ki = std::numeric_limits<double>::quiet_NaN();  // 1/(K s)
  double m_min = 0.2, m_max = 2.0;                       // limits of the commanded flow factor
  double tau_film = 3.0;                                 // s, >= 0: the film's first-order lag behind the command
  // Feedforward from the measured flux (NaN: off): the steady efficiency eta at the set point.
  // The PI then corrects around m_ff = (f - (1 - eta)) / eta instead of around 1 (below).
  double feedforward_efficiency = std::numeric_limits<double>::quiet_NaN();
  IntegratorSettings integrator;
  // The film at flow factor m (relative to the initial flow), carrying that flow, on the same
  // grid (above). Empty: the film keeps its geometry and m scales its mass fluxes.
  std::function<std::unique_ptr<FilmOperator>(double m)> film_at;
  double refilm_step = 0.02;  // a new film once the applied flow has moved this fraction from the film's
};

// One sample per control instant t = k dt_control (and t_end).
struct ControlSample {
  double t = 0.0;              // s
  double flux_factor = 0.0;    // FilmModel::flux_time at t
  double m_cmd = 0.0;          // commanded flow factor from t on
  double m = 0.0;              // applied flow factor at t
  double mass_flow = 0.0;      // kg/s (m times the initial mass flow)
  double T_out = 0.0;          // mixing-cup outlet temperature, K
  double T_surface_max = 0.0;  // K
  double T_max = 0.0;          // K: the film's hottest cell
  double efficiency = 0.0;     // carried / aperture power (NaN without sunlight)
};

struct ControlledTransientResult {
  std::vector<ControlSample> samples;
  double T_set = 0.0, kp = 0.0, ki = 0.0;  // as used (K, 1/K, 1/(K s))
  std::vector<double> y_end;
  SolverStats stats;
  // With film_at: the films taken after the first, and the film enthalpy their changes created
  // (net, and the sum of magnitudes), J.
  int refilms = 0;
  double refilm_enthalpy = 0.0, refilm_enthalpy_abs = 0.0;
};

// Integrates the film from y0 (normally the steady state at flow factor 1) to s.t_end with the
// flux history of op's model and the mass flow set by the controller (or held). The model's
// flow_time must be constant 1 (the controller owns it); op's time factors are restored on
// return. Throws std::invalid_argument for bad settings, SolverError if CVODE fails.
ControlledTransientResult run_controlled_transient(FilmOperator& op, const std::vector<double>& y0,
                                                   const ControlledTransientSettings& s);

// First order plus dead time fitted to a step response y(t) (t from 0, the step at t = 0, y
// settled at its last sample) by the two-point rule above.
struct FopdtFit {
  double change = 0.0;          // y(end) - y(0)
  double dead_time = 0.0;       // theta, s (>= 0)
  double time_constant = 0.0;   // tau_1, s
  double t28 = 0.0, t63 = 0.0;  // s
  double max_misfit = 0.0;      // largest |measured - fitted| over the samples, fraction of |change|
};
// Throws std::invalid_argument if the response does not change or never crosses 63.2 %.
FopdtFit fit_first_order_dead_time(const std::vector<double>& t, const std::vector<double>& y);

struct PiGains {
  double kp = 0.0, ki = 0.0;                         // 1/K, 1/(K s)
  double tau_c = 0.0, tau_i = 0.0, theta_eff = 0.0;  // s
};
// SIMC PI for the process gain K (output per unit input; its sign is dropped: the action is
// fixed, too hot -> more flow), sampled every dt_control; tau_c NaN: theta_eff.
PiGains simc_pi_gains(double K, double dead_time, double time_constant, double dt_control,
                      double tau_c = std::numeric_limits<double>::quiet_NaN());

struct OutletTuning {
  double step = 0.0;                          // commanded flow-factor step of the test
  double T_out_start = 0.0, T_out_end = 0.0;  // K
  double gain = 0.0;                          // dT_out/dm, K per unit flow factor (negative)
  FopdtFit fit;
  PiGains gains;
};
// Measures T_out's response to a commanded flow step 1 -> 1 + step (open loop, through the lag
// s.tau_film, flux held at its t = 0 value, 401 samples over 8 (residence time + tau_film),
// exp(-8) of a first-order approach left), fits FOPDT and gives the SIMC gains for
// s.dt_control. Throws if T_out does not fall with more flow.
OutletTuning tune_outlet_controller(FilmOperator& op, const std::vector<double>& y0,
                                    const ControlledTransientSettings& s, double step = 0.05);

}  // namespace centrec::thermal
