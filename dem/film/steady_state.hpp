#pragma once
// Steady state of the drum (paper section 4, Fig 2: "the mean outlet mass flow rate is
// equal to inlet mass flow rate"): the first time at which inlet and outlet mass flow,
// each averaged over a trailing window (a number of drum turns), agree within a relative
// tolerance.
//
// Series convention: sample i is the mean rate over (t[i-1], t[i]] (mass counted since the
// previous sample / dt), so the window means are exact integrals of the piecewise-constant
// rate; sample 0 only marks the start time t[0].
#include <cstddef>

namespace centrec::film {

struct SteadyStateCriterion {
  double window = 0.0;      // s, trailing window (see turns_to_seconds)
  double tolerance = 0.02;  // |<mdot_out> - <mdot_in>| <= tolerance * <mdot_in>
};

struct SteadyStateResult {
  bool steady = false;
  double time = 0.0;         // s: end of the first window that passes (NaN if none)
  double inlet_mean = 0.0;   // kg/s over that window (or the last full window if none passes)
  double outlet_mean = 0.0;  // kg/s
};

// n >= 2 strictly increasing times. Throws std::invalid_argument on bad input.
SteadyStateResult find_steady_state(const double* t, const double* mdot_in, const double* mdot_out, std::size_t n,
                                    const SteadyStateCriterion& c);

// Duration of `turns` drum turns at angular speed omega (rad/s).
double turns_to_seconds(double turns, double omega);

}  // namespace centrec::film
