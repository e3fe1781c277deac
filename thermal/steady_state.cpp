#include "steady_state.hpp"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <cmath>
#include <cstdio>

namespace centrec::thermal {

namespace {
// Damped Newton on f(y) = 0 with the system's band Jacobian. Returns the iterations used;
// y and residual hold the best state found.
int newton_polish(OdeSystem& sys, std::vector<double>& y, double& residual, const SteadySettings& s,
                  int max_iterations) {
  const long n = sys.size();
  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx);
  SUNMatrix A = SUNBandMatrix(n, sys.upper_bandwidth(), sys.lower_bandwidth(), ctx);
  SUNLinearSolver LS = SUNLinSol_Band(x, A, ctx);
  std::vector<double> f(n), trial(n);
  int it = 0;
  for (; it < max_iterations && residual > s.tolerance; ++it) {
    if (!sys.rhs(0.0, y.data(), f.data())) break;
    SUNMatZero(A);
    const BandEntrySink sink = [A](long r, long c, double v) { SM_ELEMENT_B(A, r, c) = v; };
    if (!sys.jacobian(0.0, y.data(), f.data(), sink)) break;
    if (SUNLinSolSetup(LS, A) != 0) break;  // singular
    double* pb = N_VGetArrayPointer(b);
    for (long k = 0; k < n; ++k) pb[k] = -f[k];
    if (SUNLinSolSolve(LS, A, x, b, 0.0) != 0) break;
    const double* dx = N_VGetArrayPointer(x);
    bool improved = false;
    for (double lambda = 1.0; lambda > 1e-3; lambda *= 0.5) {
      for (long k = 0; k < n; ++k) trial[k] = y[k] + lambda * dx[k];
      const double r = sys.steady_residual(0.0, trial.data());
      if (r < residual) {
        y.swap(trial);
        residual = r;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(x);
  N_VDestroy(b);
  SUNContext_Free(&ctx);
  return it;
}
}  // namespace

SteadyResult solve_steady(OdeSystem& sys, const std::vector<double>& y0, const SteadySettings& s) {
  SteadyResult r;
  r.y = y0;
  r.residual = sys.steady_residual(0.0, r.y.data());
  if (s.newton_first && r.residual > s.tolerance) {
    std::vector<double> y = r.y;
    double res = r.residual;
    const int it = newton_polish(sys, y, res, s, s.max_newton_first);
    r.newton_iterations += it;
    if (res <= s.tolerance) {
      r.y = y;
      r.residual = res;
      return r;
    }
  }
  const double tau = sys.time_scale();
  CvodeIntegrator cv(sys, s.integrator, 0.0, r.y);
  double t = 0.0, t_next = 0.05 * tau;
  bool restart = false;
  while (r.residual > s.tolerance) {
    if (r.residual < s.polish_below) {
      const double before = r.residual;
      r.newton_iterations += newton_polish(sys, r.y, r.residual, s, s.max_newton);
      if (r.residual <= s.tolerance) break;
      restart = r.residual < before;  // Newton moved y: CVODE must restart from there
    }
    if (t >= s.max_time_factor * tau) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "no steady state after marching %.4g s (%.0f time scales): scaled residual %.3g > tolerance "
                    "%.3g; the operating point may oscillate or the tolerance is below round-off",
                    t, s.max_time_factor, r.residual, s.tolerance);
      throw SolverError(buf);
    }
    if (restart) cv.reinit(t, r.y);
    restart = false;
    cv.advance(t_next, r.y);
    t = t_next;
    t_next *= 2.0;
    r.residual = sys.steady_residual(t, r.y.data());
  }
  r.march_time = t;
  r.marched = true;
  r.stats = cv.stats();
  return r;
}

}  // namespace centrec::thermal
