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

#include "band_solve.hpp"
#include "cavity_radiation.hpp"

namespace centrec::thermal {

namespace {
// The band Jacobian of the system at a state, factorised (SUNDIALS band LU), with the
// optional low-rank part U V^T folded in by the Woodbury identity:
// J^-1 b = x - Z (I + V^T Z)^-1 V^T x, x = J_band^-1 b, Z = J_band^-1 U.
class Factorisation {
 public:
  explicit Factorisation(OdeSystem& sys) : sys_(sys), n_(sys.size()) {
    SUNContext_Create(nullptr, &ctx_);
    x_ = N_VNew_Serial(n_, ctx_);
    b_ = N_VNew_Serial(n_, ctx_);
    A_ = SUNBandMatrix(n_, sys.upper_bandwidth(), sys.lower_bandwidth(), ctx_);
    LS_ = SUNLinSol_Band(x_, A_, ctx_);
  }
  ~Factorisation() {
    SUNLinSolFree(LS_);
    SUNMatDestroy(A_);
    N_VDestroy(x_);
    N_VDestroy(b_);
    SUNContext_Free(&ctx_);
  }
  Factorisation(const Factorisation&) = delete;
  Factorisation& operator=(const Factorisation&) = delete;

  // Jacobian at y (f = f(y)), its LU and the low-rank correction. False if singular.
  bool factor(const std::vector<double>& y, const std::vector<double>& f) {
    valid_ = false;
    SUNMatZero(A_);
    SUNMatrix A = A_;
    const BandEntrySink sink = [A](long r, long c, double v) { SM_ELEMENT_B(A, r, c) = v; };
    if (!sys_.jacobian(0.0, y.data(), f.data(), sink)) return false;
    if (SUNLinSolSetup(LS_, A_) != 0) return false;
    std::vector<double> U;
    r_ = sys_.low_rank_jacobian(0.0, y.data(), U, V_);
    if (r_ > 0) {
      // Z = J_band^-1 U, n x r row-major, all columns in one sweep over the band factors.
      Z_.resize(static_cast<std::size_t>(n_) * r_);
      for (int j = 0; j < r_; ++j)
        for (long k = 0; k < n_; ++k) Z_[static_cast<std::size_t>(k) * r_ + j] = U[static_cast<std::size_t>(j) * n_ + k];
      band_solve_many(A_, LS_, Z_.data(), r_);
      // V is sparse (one ring's top cells per column): keep its nonzeros.
      nz_.assign(r_, {});
      for (int i = 0; i < r_; ++i)
        for (long k = 0; k < n_; ++k)
          if (V_[static_cast<std::size_t>(i) * n_ + k] != 0.0) nz_[i].push_back(k);
      std::vector<double> C(static_cast<std::size_t>(r_) * r_, 0.0);
      for (int i = 0; i < r_; ++i) {
        const double* Vi = &V_[static_cast<std::size_t>(i) * n_];
        for (int j = 0; j < r_; ++j) {
          double s = i == j ? 1.0 : 0.0;
          for (long k : nz_[i]) s += Vi[k] * Z_[static_cast<std::size_t>(k) * r_ + j];
          C[static_cast<std::size_t>(i) * r_ + j] = s;
        }
      }
      try {
        Cinv_ = dense_inverse(std::move(C), r_);
      } catch (const std::exception&) {
        return false;
      }
    }
    valid_ = true;
    return true;
  }
  bool valid() const { return valid_; }
  void invalidate() { valid_ = false; }

  // dx = -J^-1 f.
  bool solve(const std::vector<double>& f, std::vector<double>& dx) {
    double* pb = N_VGetArrayPointer(b_);
    for (long k = 0; k < n_; ++k) pb[k] = -f[k];
    if (SUNLinSolSolve(LS_, A_, x_, b_, 0.0) != 0) return false;
    const double* px = N_VGetArrayPointer(x_);
    dx.assign(px, px + n_);
    if (r_ == 0) return true;
    std::vector<double> w(r_, 0.0);
    for (int i = 0; i < r_; ++i) {
      const double* Vi = &V_[static_cast<std::size_t>(i) * n_];
      for (long k : nz_[i]) w[i] += Vi[k] * dx[k];
    }
    std::vector<double> c(r_);
    for (int j = 0; j < r_; ++j) {
      double cj = 0.0;
      for (int i = 0; i < r_; ++i) cj += Cinv_[static_cast<std::size_t>(j) * r_ + i] * w[i];
      c[j] = cj;
    }
    for (long k = 0; k < n_; ++k) {
      const double* Zk = &Z_[static_cast<std::size_t>(k) * r_];
      double x = dx[k];
      for (int j = 0; j < r_; ++j) x -= Zk[j] * c[j];
      dx[k] = x;
    }
    return true;
  }

 private:
  OdeSystem& sys_;
  long n_;
  SUNContext ctx_ = nullptr;
  N_Vector x_ = nullptr, b_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver LS_ = nullptr;
  int r_ = 0;
  std::vector<double> V_, Z_, Cinv_;  // V column-major n x r, Z row-major n x r
  std::vector<std::vector<long>> nz_;
  bool valid_ = false;
};

// A step whose residual falls by less than this factor asks for a fresh Jacobian.
constexpr double kReuseContraction = 0.5;

// Damped Newton on f(y) = 0 with the system's band Jacobian (and low-rank part). The
// factorised Jacobian is kept for the next step while a step contracts the residual by
// kReuseContraction or better (chord steps: one right-hand side and one back-substitution
// instead of a Jacobian, a band LU and one back-substitution per low-rank column); a
// reused Jacobian that no longer reduces the residual is refreshed before giving up.
// Returns the steps taken; y and residual hold the best state found.
int newton_polish(OdeSystem& sys, std::vector<double>& y, double& residual, const SteadySettings& s,
                  int max_iterations) {
  double tolerance = steady_tolerance(sys, y, s);
  const long n = sys.size();
  Factorisation J(sys);
  std::vector<double> f(n), dx(n), trial(n);
  int it = 0, jacobians = 0;
  while (jacobians < max_iterations && it < 4 * max_iterations && residual > tolerance) {
    if (!sys.rhs(0.0, y.data(), f.data())) break;
    const bool fresh = !J.valid();
    if (fresh) {
      if (!J.factor(y, f)) break;
      ++jacobians;
    }
    if (!J.solve(f, dx)) break;
    const double before = residual;
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
      if (!fresh) break;  // a reused Jacobian is refreshed rather than damped
    }
    if (improved) ++it;
    if (!improved && fresh) break;
    if (!improved || residual > kReuseContraction * before) J.invalidate();
  }
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
