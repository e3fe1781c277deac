#include "steady_state.hpp"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "cavity_radiation.hpp"

namespace centrec::thermal {

namespace {
// With a low-rank Jacobian part J = J_band + U V^T: x = J_band^-1 b is turned into the
// solution of J x = b by the Woodbury identity, x -= Z (I + V^T Z)^-1 V^T x, Z = J_band^-1 U.
bool apply_low_rank(OdeSystem& sys, const std::vector<double>& y, SUNLinearSolver LS, SUNMatrix A, N_Vector x) {
  std::vector<double> U, V;
  const int r = sys.low_rank_jacobian(0.0, y.data(), U, V);
  if (r == 0) return true;
  const long n = sys.size();
  N_Vector col = N_VClone(x), rhs = N_VClone(x);
  std::vector<double> Z(static_cast<std::size_t>(n) * r);
  bool ok = true;
  for (int j = 0; j < r && ok; ++j) {
    double* pr = N_VGetArrayPointer(rhs);
    for (long k = 0; k < n; ++k) pr[k] = U[static_cast<std::size_t>(j) * n + k];
    ok = SUNLinSolSolve(LS, A, col, rhs, 0.0) == 0;
    const double* pc = N_VGetArrayPointer(col);
    for (long k = 0; k < n; ++k) Z[static_cast<std::size_t>(j) * n + k] = pc[k];
  }
  N_VDestroy(col);
  N_VDestroy(rhs);
  if (!ok) return false;
  std::vector<double> C(static_cast<std::size_t>(r) * r, 0.0), w(r, 0.0);
  double* px = N_VGetArrayPointer(x);
  std::vector<long> nz;  // V is sparse (one ring's top cells per column): loop over its nonzeros
  for (int i = 0; i < r; ++i) {
    const double* Vi = &V[static_cast<std::size_t>(i) * n];
    nz.clear();
    for (long k = 0; k < n; ++k)
      if (Vi[k] != 0.0) nz.push_back(k);
    for (long k : nz) w[i] += Vi[k] * px[k];
    for (int j = 0; j < r; ++j) {
      double s = i == j ? 1.0 : 0.0;
      const double* Zj = &Z[static_cast<std::size_t>(j) * n];
      for (long k : nz) s += Vi[k] * Zj[k];
      C[static_cast<std::size_t>(i) * r + j] = s;
    }
  }
  std::vector<double> Cinv;
  try {
    Cinv = dense_inverse(std::move(C), r);
  } catch (const std::exception&) {
    return false;
  }
  for (int j = 0; j < r; ++j) {
    double cj = 0.0;
    for (int i = 0; i < r; ++i) cj += Cinv[static_cast<std::size_t>(j) * r + i] * w[i];
    const double* Zj = &Z[static_cast<std::size_t>(j) * n];
    for (long k = 0; k < n; ++k) px[k] -= Zj[k] * cj;
  }
  return true;
}

// Damped Newton on f(y) = 0 with the system's band Jacobian. Returns the iterations used;
// y and residual hold the best state found.
int newton_polish(OdeSystem& sys, std::vector<double>& y, double& residual, const SteadySettings& s,
                  int max_iterations) {
  double tolerance = steady_tolerance(sys, y, s);
  const long n = sys.size();
  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx);
  SUNMatrix A = SUNBandMatrix(n, sys.upper_bandwidth(), sys.lower_bandwidth(), ctx);
  SUNLinearSolver LS = SUNLinSol_Band(x, A, ctx);
  std::vector<double> f(n), trial(n);
  int it = 0;
  for (; it < max_iterations && residual > tolerance; ++it) {
    if (!sys.rhs(0.0, y.data(), f.data())) break;
    SUNMatZero(A);
    const BandEntrySink sink = [A](long r, long c, double v) { SM_ELEMENT_B(A, r, c) = v; };
    if (!sys.jacobian(0.0, y.data(), f.data(), sink)) break;
    if (SUNLinSolSetup(LS, A) != 0) break;  // singular
    double* pb = N_VGetArrayPointer(b);
    for (long k = 0; k < n; ++k) pb[k] = -f[k];
    if (SUNLinSolSolve(LS, A, x, b, 0.0) != 0) break;
    if (!apply_low_rank(sys, y, LS, A, x)) break;
    const double* dx = N_VGetArrayPointer(x);
    bool improved = false;
    for (double lambda = 1.0; lambda > 1e-3; lambda *= 0.5) {
      for (long k = 0; k < n; ++k) trial[k] = y[k] + lambda * dx[k];
      const double r = sys.steady_residual(0.0, trial.data());
      if (r < residual) {
        y.swap(trial);
        residual = r;
        improved = true;
        tolerance = steady_tolerance(sys, y, s);
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
// The system with a wall-clock budget: past the deadline its right-hand side and Jacobian
// fail, which stops CVODE within a few steps; solve_steady then reports the budget.
class Budgeted : public OdeSystem {
 public:
  Budgeted(OdeSystem& sys, double seconds)
      : sys_(sys),
        deadline_(std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds))) {}
  bool expired() const { return std::chrono::steady_clock::now() > deadline_; }
  long size() const override { return sys_.size(); }
  long lower_bandwidth() const override { return sys_.lower_bandwidth(); }
  long upper_bandwidth() const override { return sys_.upper_bandwidth(); }
  bool rhs(double t, const double* y, double* ydot) override { return !expired() && sys_.rhs(t, y, ydot); }
  bool jacobian(double t, const double* y, const double* fy, const BandEntrySink& sink) override {
    return !expired() && sys_.jacobian(t, y, fy, sink);
  }
  double steady_residual(double t, const double* y) override { return sys_.steady_residual(t, y); }
  double steady_residual_floor(double t, const double* y) override { return sys_.steady_residual_floor(t, y); }
  double time_scale() const override { return sys_.time_scale(); }
  int low_rank_jacobian(double t, const double* y, std::vector<double>& U, std::vector<double>& V) override {
    return sys_.low_rank_jacobian(t, y, U, V);
  }

 private:
  OdeSystem& sys_;
  std::chrono::steady_clock::time_point deadline_;
};

[[noreturn]] void out_of_time(double seconds, double t, double residual, double tolerance) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "no steady state within the wall-time budget of %.4g s (thermal.solver.max_wall_time): marched "
                "%.4g s, scaled residual %.3g > tolerance %.3g; the operating point may be far from any steady "
                "state (a flux the flow cannot carry away, a film that hardly moves)",
                seconds, t, residual, tolerance);
  throw SolverError(buf);
}
}  // namespace

double steady_tolerance(OdeSystem& system, const std::vector<double>& y, const SteadySettings& settings) {
  return std::max(settings.tolerance, settings.round_off_factor * system.steady_residual_floor(0.0, y.data()));
}

SteadyResult solve_steady(OdeSystem& outer, const std::vector<double>& y0, const SteadySettings& s) {
  Budgeted sys(outer, s.max_wall_seconds);
  SteadyResult r;
  r.y = y0;
  r.residual = sys.steady_residual(0.0, r.y.data());
  auto finish = [&](SteadyResult& res) {
    res.residual_floor = sys.steady_residual_floor(0.0, res.y.data());
    res.tolerance = steady_tolerance(sys, res.y, s);
  };
  if (s.newton_first && r.residual > steady_tolerance(sys, r.y, s)) {
    std::vector<double> y = r.y;
    double res = r.residual;
    const int it = newton_polish(sys, y, res, s, s.max_newton_first);
    r.newton_iterations += it;
    if (res <= steady_tolerance(sys, y, s)) {
      r.y = y;
      r.residual = res;
      finish(r);
      return r;
    }
  }
  const double tau = sys.time_scale();
  CvodeIntegrator cv(sys, s.integrator, 0.0, r.y);
  double t = 0.0, t_next = 0.05 * tau;
  bool restart = false;
  while (r.residual > steady_tolerance(sys, r.y, s)) {
    if (r.residual < s.polish_below) {
      const double before = r.residual;
      r.newton_iterations += newton_polish(sys, r.y, r.residual, s, s.max_newton);
      if (r.residual <= steady_tolerance(sys, r.y, s)) break;
      restart = r.residual < before;  // Newton moved y: CVODE must restart from there
    }
    if (t >= s.max_time_factor * tau) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "no steady state after marching %.4g s (%.0f time scales): scaled residual %.3g > tolerance "
                    "%.3g (round-off level %.3g); the operating point may oscillate",
                    t, s.max_time_factor, r.residual, steady_tolerance(sys, r.y, s),
                    sys.steady_residual_floor(0.0, r.y.data()));
      throw SolverError(buf);
    }
    if (restart) cv.reinit(t, r.y);
    restart = false;
    if (sys.expired()) out_of_time(s.max_wall_seconds, t, r.residual, steady_tolerance(sys, r.y, s));
    try {
      cv.advance(t_next, r.y);
    } catch (const SolverError&) {
      if (sys.expired()) out_of_time(s.max_wall_seconds, t, r.residual, steady_tolerance(sys, r.y, s));
      throw;
    }
    t = t_next;
    t_next *= 2.0;
    r.residual = sys.steady_residual(t, r.y.data());
  }
  r.march_time = t;
  r.marched = true;
  r.stats = cv.stats();
  finish(r);
  return r;
}

}  // namespace centrec::thermal
