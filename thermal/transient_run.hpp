#pragma once
// Transient of the film (docs/thermal_model.md): a flux step, a passing cloud or a change of
// mass flow, as time factors in the FilmModel, integrated with CVODE from a given state
// (normally the steady state of the initial operating point). The integrator restarts at
// every kink of the time factors so that no BDF step straddles one.
#include <vector>

#include "cvode_integrator.hpp"
#include "film_operator.hpp"

namespace centrec::thermal {

struct TransientSettings {
  double t_end = 60.0;   // s
  int n_outputs = 121;   // samples including t = 0 and t_end
  IntegratorSettings integrator;
};

struct TransientSample {
  double t = 0.0;
  FilmBalance balance;
  double T_surface_max = 0.0;  // K
};

struct TransientResult {
  std::vector<TransientSample> samples;
  std::vector<double> y_end;
  SolverStats stats;
};

// Throws SolverError (time, flag, likely cause) if CVODE fails.
TransientResult run_transient(FilmOperator& op, const std::vector<double>& y0, const TransientSettings& s);

}  // namespace centrec::thermal
