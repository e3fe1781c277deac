// Manufactured solution T = T0 + A sin(pi z / 2L) cos(pi eta / t) with constant properties:
// the source term makes it exact, and grid refinement (nz and nxi doubled together) shows
// the observed order of accuracy: 2 for central conduction (resting film),
// 1 for upwind advection, 2 for van Leer MUSCL advection on this smooth solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "film_test_cases.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;
using namespace centrec::thermal::testcases;

namespace {
constexpr double kL = 0.1, kT = 0.01, kT0 = 500.0, kA = 100.0, kK = 1.0, kCp = 1000.0, kPhi = 0.55;

double exact(double z, double eta) { return kT0 + kA * std::sin(M_PI * z / (2 * kL)) * std::cos(M_PI * eta / kT); }

// Max-norm error of the steady solution on an (n x n/2) grid.
double mms_error(double u, Advection adv, int n) {
  FilmModel m;
  remove_losses(m);
  m.flux.q = 0.0;
  m.T_in = kT0;
  m.heat.cp_constant = kCp;
  m.conductivity.k_constant = kK;
  m.conductivity.mixing = false;
  const double rho_c = m.material.rho_s * kPhi * kCp;
  // Steady: rho c u dT/dz - k (T_zz + T_eta_eta) = S.
  m.source = [=](double z, double eta, double) {
    const double a = M_PI / (2 * kL), b = M_PI / kT;
    const double s = std::sin(a * z), c = std::cos(a * z), ce = std::cos(b * eta);
    return rho_c * u * kA * a * c * ce + kK * kA * (a * a + b * b) * s * ce;
  };
  FilmGridSpec spec;
  spec.nz = n;
  spec.nxi = n / 2;
  spec.advection = adv;
  FilmOperator op(plug_film(kT, u, kPhi, 1.0, kL), m, spec);
  op.freeze_inputs(true);
  SteadySettings s;
  s.tolerance = 1e-9;  // residual scaled by a 1 K change over the conduction time
  const SteadyResult r = solve_steady(op, op.uniform_state(kT0), s);
  const FilmGrid& g = op.grid();
  double err = 0.0;
  for (int i = 0; i < g.nz; ++i)
    for (int j = 0; j < g.nxi; ++j) err = std::max(err, std::abs(r.y[g.index(i, j)] - exact(g.zc[i], g.eta_center(i, j))));
  return err;
}

double observed_order(const char* label, double u, Advection adv) {
  const double e1 = mms_error(u, adv, 32), e2 = mms_error(u, adv, 64), e3 = mms_error(u, adv, 128);
  const double p = std::log2(e2 / e3);
  std::printf("%s: max error %.3e, %.3e, %.3e K on nz = 32, 64, 128; observed order %.2f (then %.2f)\n", label, e1, e2,
              e3, std::log2(e1 / e2), p);
  return p;
}
}  // namespace

TEST(FilmManufacturedSolution, CentralConductionIsSecondOrder) {
  const double p = observed_order("conduction only (u = 0)", 0.0, Advection::upwind);
  std::printf("  expected 2, accept [1.9, 2.1]\n");
  EXPECT_GT(p, 1.9);
  EXPECT_LT(p, 2.1);
}

TEST(FilmManufacturedSolution, UpwindAdvectionIsFirstOrder) {
  // u chosen so that advection dominates the error (Peclet u L / alpha ~ 2000).
  const double p = observed_order("upwind advection", 1e-2, Advection::upwind);
  std::printf("  expected 1, accept [0.85, 1.2]\n");
  EXPECT_GT(p, 0.85);
  EXPECT_LT(p, 1.2);
}

TEST(FilmManufacturedSolution, VanLeerAdvectionIsSecondOrderOnSmoothSolution) {
  const double p = observed_order("van Leer advection", 1e-2, Advection::van_leer);
  std::printf("  expected ~2 (limiter inactive on a monotone profile), accept [1.7, 2.3]\n");
  EXPECT_GT(p, 1.7);
  EXPECT_LT(p, 2.3);
}
