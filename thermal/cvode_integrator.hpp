#pragma once
// SUNDIALS CVODE (BDF, Newton iteration, band or KLU sparse direct linear solver) over an OdeSystem
// (docs/thermal_model.md and docs/architecture.md: the integrator knows nothing of films). Failures become
// SolverError messages naming the time, the CVODE flag and a likely cause.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ode_system.hpp"

namespace centrec::thermal {

class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class LinearSolver { band, klu };

struct IntegratorSettings {
  double rtol = 1e-6;        // relative tolerance
  double atol = 1e-4;        // absolute tolerance on T, K
  long max_steps = 50000;    // per advance() call
  int max_order = 5;         // BDF order limit
  LinearSolver linear_solver = LinearSolver::band;  // SUNDIALS band LU, or KLU sparse LU
  // Throws std::invalid_argument if a tolerance is outside what double precision supports.
  void check() const;
};

struct SolverStats {
  long steps = 0, rhs_evals = 0, newton_iterations = 0, newton_failures = 0, error_test_failures = 0,
       jacobian_evals = 0, linear_setups = 0;
  double last_step = 0.0;
  SolverStats& operator+=(const SolverStats& o);
};

class CvodeIntegrator {
 public:
  CvodeIntegrator(OdeSystem& system, const IntegratorSettings& settings, double t0, const std::vector<double>& y0);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // Integrates to exactly t_out (never past it) and writes y(t_out); throws SolverError.
  void advance(double t_out, std::vector<double>& y);
  // Restarts from (t0, y0) (after an outside change of y, or a discontinuity in the inputs).
  void reinit(double t0, const std::vector<double>& y0);
  SolverStats stats() const;
  double time() const { return t_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double t_ = 0.0;
};

}  // namespace centrec::thermal
