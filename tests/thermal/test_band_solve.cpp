// The many-right-hand-side band solve of the steady Newton (thermal/band_solve.hpp) against
// SUNDIALS' own single solves with the same LU: bitwise equal on a random band matrix that
// needs row interchanges, and A x = b to round-off (1e-12 of the terms).
#include <gtest/gtest.h>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "thermal/band_solve.hpp"

using centrec::thermal::band_solve_many;

TEST(BandSolve, ManyRightHandSidesEqualSingleSolvesBitwise) {
  const long n = 500, mu = 7, ml = 13;
  const int r = 5;
  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  SUNMatrix A = SUNBandMatrix(n, mu, ml, ctx), A0 = SUNBandMatrix(n, mu, ml, ctx);
  N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx);
  SUNLinearSolver LS = SUNLinSol_Band(x, A, ctx);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  // Rows diagonally dominant (well conditioned) but scaled by factors 1-1000, so that a
  // column's entry below the diagonal often exceeds the diagonal: partial pivoting
  // interchanges rows.
  std::uniform_real_distribution<double> E(0.0, 3.0);
  for (long row = 0; row < n; ++row) {
    const double scale = std::pow(10.0, E(rng));
    double off = 0.0;
    for (long c = std::max(0L, row - ml); c <= std::min(n - 1, row + mu); ++c) {
      if (c == row) continue;
      const double v = scale * U(rng);
      off += std::abs(v);
      SM_ELEMENT_B(A, row, c) = SM_ELEMENT_B(A0, row, c) = v;
    }
    SM_ELEMENT_B(A, row, row) = SM_ELEMENT_B(A0, row, row) = 1.1 * off + scale;
  }
  ASSERT_EQ(SUNLinSolSetup(LS, A), 0);
  long swaps = 0;
  const sunindextype* p = static_cast<SUNLinearSolverContent_Band>(LS->content)->pivots;
  for (long k = 0; k < n; ++k) swaps += p[k] != k;
  std::vector<double> B(static_cast<std::size_t>(n) * r), rhs = B;
  for (double& v : B) v = U(rng);
  rhs = B;
  band_solve_many(A, LS, B.data(), r);
  long differ = 0;
  double worst = 0.0;
  for (int c = 0; c < r; ++c) {
    double* pb = N_VGetArrayPointer(b);
    for (long k = 0; k < n; ++k) pb[k] = rhs[static_cast<std::size_t>(k) * r + c];
    ASSERT_EQ(SUNLinSolSolve(LS, A, x, b, 0.0), 0);
    const double* px = N_VGetArrayPointer(x);
    for (long k = 0; k < n; ++k) differ += px[k] != B[static_cast<std::size_t>(k) * r + c];
    // Residual of the original matrix.
    for (long row = 0; row < n; ++row) {
      double s = -rhs[static_cast<std::size_t>(row) * r + c], mag = std::abs(s);
      for (long col = std::max(0L, row - ml); col <= std::min(n - 1, row + mu); ++col) {
        s += SM_ELEMENT_B(A0, row, col) * B[static_cast<std::size_t>(col) * r + c];
        mag += std::abs(SM_ELEMENT_B(A0, row, col) * B[static_cast<std::size_t>(col) * r + c]);
      }
      worst = std::max(worst, std::abs(s) / mag);
    }
  }
  std::printf("band %ld x %ld (mu %ld, ml %ld), %ld row interchanges, %d right-hand sides: %ld entries differ from "
              "SUNDIALS' single solves (expected 0), max |A x - b| / sum |terms| = %.2e (tolerance 1e-12)\n",
              n, n, mu, ml, swaps, r, differ, worst);
  EXPECT_GT(swaps, 0);
  EXPECT_EQ(differ, 0);
  EXPECT_LT(worst, 1e-12);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  SUNMatDestroy(A0);
  N_VDestroy(x);
  N_VDestroy(b);
  SUNContext_Free(&ctx);
}
