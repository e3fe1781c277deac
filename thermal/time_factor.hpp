#pragma once
// A dimensionless factor f(t) that scales a boundary input in time: the solar flux
// (flux step, passing cloud) or the film velocity (mass-flow change), docs/thermal_model.md.
//   constant: f = level (1 unless set)
//   step:     f goes from 1 to `level` at t_start over a linear ramp of `ramp` seconds
//   pulse:    f goes from 1 to `level` at t_start and back to 1 at t_end (a cloud), each
//             edge a linear ramp of `ramp` seconds
//   table:    piecewise linear through (table_t, table_f) (a measured cloud replayed); the
//             first value before the first time, the last after the last time
//   lag:      `from` until t_start, then a first-order approach to `level` with time constant
//             `tau`: f = level + (from - level) exp(-(t - t_start) / tau) (tau 0: a sharp step).
//             The response of a fed drum's holdup to a step of the commanded mass flow
//             (thermal/outlet_controller.hpp).
#include <vector>

namespace centrec::thermal {

struct TimeFactor {
  enum class Kind { constant, step, pulse, table, lag };
  Kind kind = Kind::constant;
  double level = 1.0;
  double t_start = 0.0;         // s
  double t_end = 0.0;           // s (pulse only)
  double ramp = 0.0;            // s, >= 0; 0 is a sharp edge
  std::vector<double> table_t;  // s, strictly increasing, >= 2 points (table only)
  std::vector<double> table_f;  // >= 0, one per time (table only)
  double from = 1.0;            // value before t_start (lag only)
  double tau = 0.0;             // s, >= 0 (lag only)

  double at(double t) const;
  // Times where f has a kink (sorted), so an integrator can stop there instead of stepping
  // over: every point of a table.
  std::vector<double> breakpoints() const;
  // Throws std::invalid_argument naming what is wrong (ramp or tau < 0, a negative factor, a
  // table that is short, not increasing or not finite).
  void check() const;
};

}  // namespace centrec::thermal
