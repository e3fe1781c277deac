#pragma once
// A dimensionless factor f(t) that scales a boundary input in time: the solar flux
// (flux step, passing cloud) or the film velocity (mass-flow change), docs/thermal_model.md.
//   constant: f = 1
//   step:     f goes from 1 to `level` at t_start over a linear ramp of `ramp` seconds
//   pulse:    f goes from 1 to `level` at t_start and back to 1 at t_end (a cloud), each
//             edge a linear ramp of `ramp` seconds

namespace centrec::thermal {

struct TimeFactor {
  enum class Kind { constant, step, pulse };
  Kind kind = Kind::constant;
  double level = 1.0;
  double t_start = 0.0;  // s
  double t_end = 0.0;    // s (pulse only)
  double ramp = 0.0;     // s, >= 0; 0 is a sharp edge

  double at(double t) const;
  // Times where f has a kink, so an integrator can stop there instead of stepping over.
  int breakpoints(double out[4]) const;
};

}  // namespace centrec::thermal
