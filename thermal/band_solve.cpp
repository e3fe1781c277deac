#include "band_solve.hpp"

#include <algorithm>

namespace centrec::thermal {

void band_solve_many(SUNMatrix A, SUNLinearSolver LS, double* B, int r) {
  // The factors as SUNDIALS' band LU stores them (column k in cols[k], diagonal at offset
  // s_mu, the negated multipliers of L below it, U above it, row interchanges in pivots).
  const sunindextype n = SM_COLUMNS_B(A), smu = SM_SUBAND_B(A), ml = SM_LBAND_B(A);
  realtype** a = SM_COLS_B(A);
  const sunindextype* p = static_cast<SUNLinearSolverContent_Band>(LS->content)->pivots;
  // L y = P b.
  for (sunindextype k = 0; k + 1 < n; ++k) {
    double* bk = B + k * r;
    if (p[k] != k) std::swap_ranges(bk, bk + r, B + p[k] * r);
    const double* dk = a[k] + smu;
    const sunindextype last = std::min(n - 1, k + ml);
    for (sunindextype i = k + 1; i <= last; ++i) {
      const double m = dk[i - k];
      double* bi = B + i * r;
      for (int c = 0; c < r; ++c) bi[c] += bk[c] * m;
    }
  }
  // U x = y.
  for (sunindextype k = n - 1; k >= 0; --k) {
    double* bk = B + k * r;
    const double* dk = a[k] + smu;
    for (int c = 0; c < r; ++c) bk[c] /= dk[0];
    const sunindextype first = std::max<sunindextype>(0, k - smu);
    for (sunindextype i = first; i < k; ++i) {
      const double m = dk[i - k];
      double* bi = B + i * r;
      for (int c = 0; c < r; ++c) bi[c] += -bk[c] * m;
    }
  }
}

}  // namespace centrec::thermal
