#pragma once
// Solves with a SUNDIALS band LU for many right-hand sides in one sweep (the steady
// Newton's low-rank correction needs J_band^-1 U for one column of U per cavity ring;
// docs/thermal_model.md, "Solvers"). The band factors of an 8000-cell film (12 MB with the
// van Leer band) do not fit in cache, so r single solves stream them 2 r times; one sweep
// over r columns streams them twice. Same operations in the same order per right-hand side
// as SUNDIALS' bandGBTRS, so the results are bitwise those of r single solves.
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

namespace centrec::thermal {

// A: factorised by SUNLinSolSetup(LS, A) with LS a SUNLinSol_Band. B: n x r, row-major
// (B[k * r + c] is row k of right-hand side c), overwritten by the solutions.
void band_solve_many(SUNMatrix A, SUNLinearSolver LS, double* B, int r);

}  // namespace centrec::thermal
