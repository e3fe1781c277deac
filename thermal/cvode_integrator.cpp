#include "cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace centrec::thermal {

void IntegratorSettings::check() const {
  // Below ~100 machine epsilons the BDF error test can never pass: refuse up front.
  const double floor = 100.0 * std::numeric_limits<double>::epsilon();
  char buf[160];
  if (!(rtol >= floor && rtol <= 0.1)) {
    std::snprintf(buf, sizeof buf, "relative tolerance %g outside [%.2g, 0.1] (double precision limit)", rtol, floor);
    throw std::invalid_argument(buf);
  }
  if (!(atol > 0.0 && atol <= 100.0)) {
    std::snprintf(buf, sizeof buf, "absolute tolerance %g K outside (0, 100]", atol);
    throw std::invalid_argument(buf);
  }
  if (max_steps < 1) throw std::invalid_argument("max_steps must be >= 1");
  if (max_order < 1 || max_order > 5) throw std::invalid_argument("BDF max_order must be in [1, 5]");
}

SolverStats& SolverStats::operator+=(const SolverStats& o) {
  steps += o.steps;
  rhs_evals += o.rhs_evals;
  newton_iterations += o.newton_iterations;
  newton_failures += o.newton_failures;
  error_test_failures += o.error_test_failures;
  jacobian_evals += o.jacobian_evals;
  linear_setups += o.linear_setups;
  last_step = o.last_step;
  return *this;
}

struct CvodeIntegrator::Impl {
  OdeSystem& sys;
  SUNContext ctx = nullptr;
  void* mem = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  std::string last_message;
  SolverStats before;  // counters at the last reinit (CVODE resets them)
  explicit Impl(OdeSystem& s) : sys(s) {}
  ~Impl() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
  SolverStats counters() const {
    SolverStats s;
    long v = 0;
    CVodeGetNumSteps(mem, &v), s.steps = v;
    CVodeGetNumRhsEvals(mem, &v), s.rhs_evals = v;
    CVodeGetNumNonlinSolvIters(mem, &v), s.newton_iterations = v;
    CVodeGetNumNonlinSolvConvFails(mem, &v), s.newton_failures = v;
    CVodeGetNumErrTestFails(mem, &v), s.error_test_failures = v;
    CVodeGetNumJacEvals(mem, &v), s.jacobian_evals = v;
    CVodeGetNumLinSolvSetups(mem, &v), s.linear_setups = v;
    double h = 0;
    CVodeGetLastStep(mem, &h);
    s.last_step = h;
    return s;
  }
};

namespace {
int rhs_fn(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* sys = static_cast<OdeSystem*>(user);
  // A positive return is a recoverable failure: CVODE retries with a smaller step.
  return sys->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : 1;
}

int jac_fn(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
  auto* sys = static_cast<OdeSystem*>(user);
  const double* py = N_VGetArrayPointer(y);
  const double* pf = N_VGetArrayPointer(fy);
  if (SUNMatGetID(J) == SUNMATRIX_BAND) {
    SUNMatZero(J);
    const BandEntrySink sink = [J](long r, long c, double v) { SM_ELEMENT_B(J, r, c) = v; };
    return sys->jacobian(t, py, pf, sink) ? 0 : 1;
  }
  // Compressed sparse columns, filled in one pass (entries arrive column by column).
  sunindextype* colptr = SUNSparseMatrix_IndexPointers(J);
  sunindextype* rowval = SUNSparseMatrix_IndexValues(J);
  double* data = SUNSparseMatrix_Data(J);
  const long n = sys->size(), capacity = SUNSparseMatrix_NNZ(J);
  long nnz = 0, column = -1;
  bool overflow = false;
  const BandEntrySink sink = [&](long r, long c, double v) {
    while (column < c) colptr[++column] = nnz;
    if (nnz >= capacity) {
      overflow = true;
      return;
    }
    rowval[nnz] = r;
    data[nnz++] = v;
  };
  if (!sys->jacobian(t, py, pf, sink) || overflow) return overflow ? -1 : 1;
  while (column < n - 1) colptr[++column] = nnz;
  colptr[n] = nnz;
  return 0;
}

void err_fn(int code, const char* module, const char* function, char* msg, void* user) {
  auto* text = static_cast<std::string*>(user);
  *text = std::string(module) + "/" + function + " (" + std::to_string(code) + "): " + msg;
}

const char* likely_cause(int flag) {
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      return "the solution changes on a time scale far shorter than the requested interval (raise "
             "solver.max_steps, or check for an unphysical flux/velocity)";
    case CV_TOO_MUCH_ACC:
      return "the tolerances are tighter than double precision allows (raise solver.rtol/atol)";
    case CV_ERR_FAILURE:
      return "repeated error-test failures: a discontinuity in the inputs inside a step, or tolerances too tight";
    case CV_CONV_FAILURE:
      return "Newton iteration failed repeatedly: a stiff, strongly nonlinear term (radiation at high T) with a "
             "stale Jacobian, or a state driven out of range";
    case CV_LSETUP_FAIL:
    case CV_LSOLVE_FAIL:
      return "the banded LU factorisation failed: a singular Jacobian (zero capacity or non-finite property)";
    case CV_RHSFUNC_FAIL:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_FIRST_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR:
      return "the right-hand side rejected the state (non-positive or non-finite temperature): the step "
             "overshoots, e.g. a flux far too high for the film, or an unstable input";
    case CV_ILL_INPUT:
      return "an input to CVODE is illegal (tolerances, output time behind the current time)";
    default:
      return "see the CVODE message";
  }
}

void check_flag(int flag, const char* what) {
  if (flag < 0) throw SolverError(std::string("CVODE setup failed in ") + what + " (flag " + std::to_string(flag) + ")");
}
}  // namespace

CvodeIntegrator::CvodeIntegrator(OdeSystem& system, const IntegratorSettings& s, double t0,
                                 const std::vector<double>& y0)
    : impl_(std::make_unique<Impl>(system)), t_(t0) {
  s.check();
  const long n = system.size();
  if (static_cast<long>(y0.size()) != n) throw std::invalid_argument("CVODE: initial state has the wrong size");
  Impl& m = *impl_;
  check_flag(SUNContext_Create(nullptr, &m.ctx), "SUNContext_Create");
  m.y = N_VNew_Serial(n, m.ctx);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(m.y));
  m.mem = CVodeCreate(CV_BDF, m.ctx);
  if (!m.mem) throw SolverError("CVodeCreate failed");
  check_flag(CVodeInit(m.mem, rhs_fn, t0, m.y), "CVodeInit");
  check_flag(CVodeSetUserData(m.mem, &system), "CVodeSetUserData");
  check_flag(CVodeSetErrHandlerFn(m.mem, err_fn, &m.last_message), "CVodeSetErrHandlerFn");
  check_flag(CVodeSStolerances(m.mem, s.rtol, s.atol), "CVodeSStolerances");
  check_flag(CVodeSetMaxNumSteps(m.mem, s.max_steps), "CVodeSetMaxNumSteps");
  check_flag(CVodeSetMaxOrd(m.mem, s.max_order), "CVodeSetMaxOrd");
  if (s.linear_solver == LinearSolver::klu) {
    // Room for the whole band: the sparsity is at most that.
    const long nnz = n * (system.lower_bandwidth() + system.upper_bandwidth() + 1);
    m.A = SUNSparseMatrix(n, n, nnz, CSC_MAT, m.ctx);
    m.LS = SUNLinSol_KLU(m.y, m.A, m.ctx);
  } else {
    m.A = SUNBandMatrix(n, system.upper_bandwidth(), system.lower_bandwidth(), m.ctx);
    m.LS = SUNLinSol_Band(m.y, m.A, m.ctx);
  }
  if (!m.A || !m.LS) throw SolverError("CVODE: cannot allocate the Jacobian matrix/linear solver");
  check_flag(CVodeSetLinearSolver(m.mem, m.LS, m.A), "CVodeSetLinearSolver");
  check_flag(CVodeSetJacFn(m.mem, jac_fn), "CVodeSetJacFn");
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::reinit(double t0, const std::vector<double>& y0) {
  Impl& m = *impl_;
  m.before += m.counters();
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(m.y));
  check_flag(CVodeReInit(m.mem, t0, m.y), "CVodeReInit");
  t_ = t0;
}

void CvodeIntegrator::advance(double t_out, std::vector<double>& y) {
  Impl& m = *impl_;
  if (t_out > t_) {
    CVodeSetStopTime(m.mem, t_out);
    realtype t_reached = t_;
    const int flag = CVode(m.mem, t_out, m.y, &t_reached, CV_NORMAL);
    if (flag < 0) {
      double t_fail = t_reached;
      CVodeGetCurrentTime(m.mem, &t_fail);
      char* name = CVodeGetReturnFlagName(flag);
      char buf[160];
      std::snprintf(buf, sizeof buf, "CVODE failed at t = %.6g s (integrating to %.6g s) with %s (flag %d): ", t_fail,
                    t_out, name, flag);
      std::free(name);
      throw SolverError(buf + std::string(likely_cause(flag)) +
                        (m.last_message.empty() ? "" : ". CVODE says: " + m.last_message));
    }
    t_ = t_out;
  }
  y.assign(N_VGetArrayPointer(m.y), N_VGetArrayPointer(m.y) + impl_->sys.size());
}

SolverStats CvodeIntegrator::stats() const {
  SolverStats s = impl_->before;
  s += impl_->counters();
  return s;
}

}  // namespace centrec::thermal
