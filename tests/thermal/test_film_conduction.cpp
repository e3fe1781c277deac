// Pure conduction across a resting film (u = 0) heated at the surface by a fixed flux and
// losing it through the wall (U_w): the steady profile is linear for constant k, and for
// the ZBS k(T) it follows the Kirchhoff transform integral(k dT) = alpha q eta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "film_test_cases.hpp"
#include "thermal/bed_conductivity.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;
using namespace centrec::thermal::testcases;

namespace {
constexpr double kThick = 6e-3, kFlux = 5e4, kUw = 50.0, kTamb = 300.0;

FilmModel resting_model() {
  FilmModel m;
  remove_losses(m);  // no emission/convection at the surface
  m.wall.adiabatic = false;
  m.wall.U_w = kUw;
  m.wall.T_amb = kTamb;
  m.flux.q = kFlux;
  m.T_in = 400.0;
  m.conductivity.axial = ConductivitySettings::Axial::none;  // uniform in z: no inlet face effect
  m.conductivity.mixing = false;
  return m;
}

std::vector<double> solve(const FilmModel& m, int nxi) {
  FilmGridSpec spec;
  spec.nz = 4;
  spec.nxi = nxi;
  FilmOperator op(plug_film(kThick, 0.0, 0.55, 1.0, 1.0), m, spec);
  op.freeze_inputs(true);
  SteadySettings s;
  s.tolerance = 1e-12;
  return solve_steady(op, op.uniform_state(m.T_in), s).y;
}
}  // namespace

TEST(FilmConduction, ConstantConductivityLinearProfileExact) {
  FilmModel m = resting_model();
  m.conductivity.k_constant = 0.4;
  const int nxi = 12;
  const std::vector<double> T = solve(m, nxi);
  const double qa = m.material.alpha * kFlux, deta = kThick / nxi;
  double err = 0.0;
  for (int j = 0; j < nxi; ++j) {
    const double exact = kTamb + qa / kUw + qa * (j + 0.5) * deta / 0.4;
    err = std::max(err, std::abs(T[2 * nxi + j] - exact));
  }
  std::printf("linear profile (wall %.3f K, surface %.3f K): max |T - exact| = %.2e K (tolerance 1e-8 K)\n",
              kTamb + qa / kUw, kTamb + qa / kUw + qa * kThick / 0.4, err);
  EXPECT_LT(err, 1e-8);
}

TEST(FilmConduction, ZbsConductivityFollowsKirchhoffProfile) {
  const FilmModel m = resting_model();
  BedConductivityModel bed;  // same defaults as the material
  const double qa = m.material.alpha * kFlux;
  // Reference: dT/deta = qa / k(T) from the wall temperature, RK4 with 20000 steps.
  auto reference = [&](double eta) {
    double T = kTamb + qa / kUw;
    const int n = 20000;
    const double h = eta / n;
    auto f = [&](double x) { return qa / bed.k_bed(x, 0.55); };
    for (int k = 0; k < n; ++k) {
      const double k1 = f(T), k2 = f(T + 0.5 * h * k1), k3 = f(T + 0.5 * h * k2), k4 = f(T + h * k3);
      T += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return T;
  };
  double errs[2];
  const int grids[2] = {20, 40};
  for (int g = 0; g < 2; ++g) {
    const int nxi = grids[g];
    const std::vector<double> T = solve(m, nxi);
    double err = 0.0;
    for (int j = 0; j < nxi; ++j) err = std::max(err, std::abs(T[2 * nxi + j] - reference((j + 0.5) * kThick / nxi)));
    errs[g] = err;
  }
  const double order = std::log2(errs[0] / errs[1]);
  std::printf("k(T) profile (surface %.2f K): max error %.3e K (nxi 20), %.3e K (nxi 40, tolerance 0.02 K); "
              "observed order %.2f (expected 2, accept 1.8-2.2)\n",
              reference(kThick), errs[0], errs[1], order);
  EXPECT_LT(errs[1], 0.02);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(order, 2.2);
}
