#pragma once
// Runs a thermal case: the steady state of the initial operating point, then the transient
// if the case has one (docs/thermal_model.md). Shared by `centrec thermal` and the tests.
#include <memory>
#include <vector>

#include "config/case_thermal.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"
#include "thermal/transient_run.hpp"

namespace centrec::runs {

struct ThermalRun {
  std::unique_ptr<thermal::FilmOperator> op;
  thermal::SteadyResult steady;
  thermal::FilmBalance balance;          // at the steady state
  thermal::ThermalFields fields;            // at the steady state
  std::vector<thermal::KeffSection> keff;
  double steady_seconds = 0.0;           // wall time of the steady solve
  bool has_transient = false;
  thermal::TransientResult transient;
  double transient_seconds = 0.0;
};

// Throws thermal::SolverError / std::invalid_argument with a clear message on failure.
// report: the phase lines on stderr (off for the error budget's many solves).
ThermalRun run_thermal_case(const config::ThermalCase& c, bool report = true);
// Throws std::runtime_error if the film's or the receiver's balance misses closing by more
// than thermal::kBalanceTolerance of its largest power (thermal/film_operator.hpp).
void check_balance(const thermal::FilmBalance& b);

}  // namespace centrec::runs
