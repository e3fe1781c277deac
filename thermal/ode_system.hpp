#pragma once
// A method-of-lines system dy/dt = f(t, y) with a banded Jacobian: what the time
// integrator and the steady-state solver see (docs/architecture.md, MFEM's
// TimeDependentOperator pattern). Integrators know nothing of films.
#include <functional>
#include <vector>

namespace centrec::thermal {

// Receives Jacobian entries J(row, col) = d f_row / d y_col inside the band.
using BandEntrySink = std::function<void(long row, long col, double value)>;

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual long size() const = 0;
  virtual long lower_bandwidth() const = 0;  // J(r, c) == 0 for r - c > lower
  virtual long upper_bandwidth() const = 0;  // J(r, c) == 0 for c - r > upper
  // Returns false if y is outside the model's domain (non-finite or non-positive T): the
  // integrator then retries with a smaller step.
  virtual bool rhs(double t, const double* y, double* ydot) = 0;
  // Writes every nonzero of the Jacobian at (t, y); fy = f(t, y) is given. Entries must
  // arrive column by column (columns increasing, rows increasing within a column, each
  // (row, col) once) so that a sparse (CSC) matrix can be filled in one pass.
  virtual bool jacobian(double t, const double* y, const double* fy, const BandEntrySink& sink) = 0;
  // A dimensionless size of f(t, y) used to decide a steady state (1 = of the order of the
  // system's throughput); the steady solver stops when it falls below its tolerance.
  virtual double steady_residual(double t, const double* y) = 0;
  // The part of steady_residual that round-off alone leaves at a steady state (same scale):
  // the steady solver asks for no less than a multiple of it, so a tolerance that is fine
  // for one problem does not lie below the round-off of another (large conductivities,
  // fine grids). 0: unknown (the tolerance is taken as given).
  virtual double steady_residual_floor(double /*t*/, const double* /*y*/) { return 0.0; }
  // Time scale of the slowest transport (residence time or conduction time), s.
  virtual double time_scale() const = 0;
  // Optional low-rank part of the Jacobian that the band cannot hold (e.g. radiation
  // exchange between distant cells): J = J_band + U V^T with U, V column-major size() x r.
  // Returns r (0: none). The steady Newton solves with it by the Woodbury identity.
  virtual int low_rank_jacobian(double /*t*/, const double* /*y*/, std::vector<double>& /*U*/,
                                std::vector<double>& /*V*/) {
    return 0;
  }
};

}  // namespace centrec::thermal
