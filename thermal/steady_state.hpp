#pragma once
// Steady state of an OdeSystem (docs/thermal_model.md): march with CVODE until the scaled
// residual is small, then polish with damped Newton steps on f(y) = 0 using the same band
// Jacobian and the SUNDIALS band LU, until the residual is below the tolerance. If Newton
// stalls, marching resumes from the best state. Optionally damped Newton is tried first
// from y0 and marching only starts if it stalls.
#include <vector>

#include "cvode_integrator.hpp"
#include "ode_system.hpp"

namespace centrec::thermal {

struct SteadySettings {
  double tolerance = 1e-10;       // on OdeSystem::steady_residual
  // The tolerance applied is max(tolerance, round_off_factor x OdeSystem::steady_residual_floor):
  // it scales with the problem where round-off would keep the residual above `tolerance`
  // (large conductivities, fine grids), and is `tolerance` everywhere else.
  double round_off_factor = 4.0;
  double polish_below = 1e-3;     // start Newton once marching brought the residual below this
  double max_time_factor = 1e4;   // give up after this many system time scales of marching
  int max_newton = 12;
  // Try damped Newton from y0 before marching (much cheaper when it converges: a few band
  // factorisations instead of one per few BDF steps); marching remains the fallback.
  bool newton_first = true;
  int max_newton_first = 25;
  // Wall-clock budget of the whole solve, s: a march that cannot reach a steady state in it
  // (a film heated far beyond any physical temperature marches ever more slowly) is stopped
  // with a SolverError saying so, instead of running for hours.
  double max_wall_seconds = 600.0;
  IntegratorSettings integrator{1e-5, 1e-3, 50000, 5};
};

struct SteadyResult {
  std::vector<double> y;
  double residual = 0.0;
  double tolerance = 0.0;    // the tolerance applied (see SteadySettings::round_off_factor)
  double residual_floor = 0.0;  // OdeSystem::steady_residual_floor at the result
  double march_time = 0.0;   // simulated time marched, s
  int newton_iterations = 0;
  bool marched = false;      // false if Newton alone converged from y0
  SolverStats stats;
};

// The tolerance applied at state y (SteadySettings::round_off_factor).
double steady_tolerance(OdeSystem& system, const std::vector<double>& y, const SteadySettings& settings);

// Throws SolverError if no steady state is reached (within max_time_factor time scales of
// marching and max_wall_seconds of wall time).
SteadyResult solve_steady(OdeSystem& system, const std::vector<double>& y0, const SteadySettings& settings);

}  // namespace centrec::thermal
