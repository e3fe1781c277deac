#pragma once
// Steady state of an OdeSystem (DESIGN.md section 9): march with CVODE until the scaled
// residual is small, then polish with damped Newton steps on f(y) = 0 using the same band
// Jacobian and the SUNDIALS band LU, until the residual is below the tolerance. If Newton
// stalls, marching resumes from the best state.
#include <vector>

#include "cvode_integrator.hpp"
#include "ode_system.hpp"

namespace centrec::thermal {

struct SteadySettings {
  double tolerance = 1e-10;       // on OdeSystem::steady_residual
  double polish_below = 1e-3;     // start Newton once marching brought the residual below this
  double max_time_factor = 1e4;   // give up after this many system time scales of marching
  int max_newton = 12;
  IntegratorSettings integrator{1e-5, 1e-3, 50000, 5};
};

struct SteadyResult {
  std::vector<double> y;
  double residual = 0.0;
  double march_time = 0.0;   // simulated time marched, s
  int newton_iterations = 0;
  SolverStats stats;
};

// Throws SolverError if no steady state is reached.
SteadyResult solve_steady(OdeSystem& system, const std::vector<double>& y0, const SteadySettings& settings);

}  // namespace centrec::thermal
