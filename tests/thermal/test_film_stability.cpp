// Where methods fail: a cell Peclet number of 1e4 with a flux that jumps along
// the film stays within the physical bounds; a radiation-dominated 1000 C film converges
// both by Newton and by marching; a film with a conductivity of 1e4-1e5 W/(m K), whose
// round-off lies above the absolute tolerance 1e-10, converges to the tolerance scaled with
// its round-off level, by Newton and by marching to the same outlet temperature (within ten
// times the tolerance applied times the temperature rise: 3e-5 K at 1e4, 2e-4 K at 1e5).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "film_test_cases.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/physical_constants.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;
using namespace centrec::thermal::testcases;

TEST(FilmStability, CellPeclet1e4StaysWithinPhysicalBounds) {
  AnalyticFilm a = centrec_film();
  a.D_shear_coeff = 0.0;
  FilmModel m = centrec_model();
  const double T0 = 600.0;
  m.T_in = m.surface.T_env = m.surface.T_air = m.wall.T_amb = T0;
  m.heat.cp_constant = 1000.0;
  m.conductivity.mixing = false;
  // Flux 0 -> 2 MW/m2 -> 0 with sharp edges at z = 0.3 m and 0.6 m.
  m.flux.kind = FluxProfile::Kind::table;
  m.flux.table_z = {0.0, 0.3, 0.3001, 0.6, 0.6001, 1.0};
  m.flux.table_q = {0.0, 0.0, 2e6, 2e6, 0.0, 0.0};
  FilmGridSpec spec;
  spec.nz = 100;
  spec.nxi = 24;
  const double dz = a.length / spec.nz;
  const double rho_c = m.material.rho_s * a.phi * m.heat.cp_constant;
  m.conductivity.k_constant = a.u_surface * dz * rho_c / 1e4;  // cell Peclet u dz / alpha = 1e4 at the surface
  const double T_eq = std::pow(m.material.alpha * 2e6 / (m.material.epsilon * kStefanBoltzmann) + std::pow(T0, 4), 0.25);
  for (Advection adv : {Advection::upwind, Advection::van_leer}) {
    spec.advection = adv;
    FilmOperator op(analytic_film(a), m, spec);
    op.freeze_inputs(true);
    const SteadyResult r = solve_steady(op, op.uniform_state(T0), SteadySettings{});
    const ThermalFields f = op.fields(0.0, r.y.data());
    const double lo = *std::min_element(r.y.begin(), r.y.end());
    const double hi = std::max(*std::max_element(r.y.begin(), r.y.end()),
                               *std::max_element(f.T_surface.begin(), f.T_surface.end()));
    std::printf("%s, cell Peclet %.0f (k = %.3g W/(m K)): T in [%.12f, %.2f] K; bounds [%.1f, %.2f] K "
                "(inlet/ambient, radiative equilibrium at peak flux)\n",
                adv == Advection::upwind ? "upwind" : "van Leer", a.u_surface * dz * rho_c / m.conductivity.k_constant,
                m.conductivity.k_constant, lo, hi, T0, T_eq);
    // 1e-6 K allows the steady solver's convergence error (~1e-9 K); an oscillation of a
    // non-monotone scheme at this Peclet number is of order 10-100 K.
    EXPECT_GE(lo, T0 - 1e-6);
    EXPECT_LE(hi, T_eq);
  }
}

TEST(FilmStability, RadiationDominated1000CConvergesByNewtonAndByMarching) {
  FilmModel m = centrec_model();
  m.T_in = 1273.15;
  m.flux.q = 3e5;
  FilmGridSpec spec;
  spec.nz = 100;
  spec.nxi = 24;
  double T_out[2];
  for (int k = 0; k < 2; ++k) {
    FilmOperator op(analytic_film(centrec_film()), m, spec);
    op.freeze_inputs(true);
    SteadySettings s;
    s.newton_first = k == 0;
    s.tolerance = 1e-10;
    const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), s);
    const FilmBalance b = op.balance(0.0, r.y.data());
    T_out[k] = b.T_out;
    std::printf("%s: residual %.2e (tolerance 1e-10), %ld BDF steps, %d Newton iterations; emitted %.3g W = %.0f%% "
                "of absorbed, T_out %.4f K\n",
                k == 0 ? "Newton first" : "marching", r.residual, r.stats.steps, r.newton_iterations, b.emitted,
                100.0 * b.emitted / b.absorbed, b.T_out);
    EXPECT_LE(r.residual, 1e-10);
    EXPECT_GT(b.emitted, 0.3 * b.absorbed);  // radiation-dominated indeed
  }
  std::printf("|T_out(Newton) - T_out(marching)| = %.2e K (tolerance 1e-6 K)\n", std::abs(T_out[0] - T_out[1]));
  EXPECT_NEAR(T_out[0], T_out[1], 1e-6);
}

TEST(FilmStability, LargeConductivityConvergesToRoundOffScaledTolerance) {
  // The CentRec operating point with a constant conductivity of 1e4 and 1e5 W/(m K) (a
  // strongly mixed film): its cell residuals cannot fall below ~3e-10 and ~3e-9 of the
  // absorbed power (a temperature's half ulp times the cell conductance), so an absolute
  // tolerance of 1e-10 is never met and the solve runs into its wall-time budget.
  for (double k : {1e4, 1e5}) {
    FilmModel m = centrec_model();
    m.conductivity.k_constant = k;
    m.conductivity.mixing = false;
    double T_out[2], tolerance = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
      FilmOperator op(analytic_film(centrec_film()), m, FilmGridSpec{});
      op.freeze_inputs(true);
      SteadySettings s;
      s.newton_first = pass == 0;
      s.max_wall_seconds = 60.0;
      const auto t0 = std::chrono::steady_clock::now();
      const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), s);
      const double seconds = seconds_since(t0);
      const FilmBalance b = op.balance(0.0, r.y.data());
      T_out[pass] = b.T_out;
      tolerance = std::max(tolerance, r.tolerance);
      // Depth spread of the outlet column: a strongly conducting film is nearly isothermal.
      const int nxi = op.grid().nxi, last = (op.grid().nz - 1) * nxi;
      const double spread = r.y[last + nxi - 1] - r.y[last];
      std::printf("k = %.0e W/(m K), %s: residual %.3g <= tolerance applied %.3g (round-off level %.3g, "
                  "absolute 1e-10), %d Newton iterations, %.2f s; T_out %.6f K, outlet depth spread %.3f K\n",
                  k, pass == 0 ? "Newton first" : "marching", r.residual, r.tolerance, r.residual_floor,
                  r.newton_iterations, seconds, b.T_out, spread);
      EXPECT_LE(r.residual, r.tolerance);
      EXPECT_GT(r.tolerance, 1e-10);                // scaled above the absolute tolerance...
      EXPECT_LT(r.tolerance, 1e-12 * k);            // ...in proportion to k, not more
      EXPECT_GT(b.T_out, m.T_in);
      EXPECT_LT(std::abs(spread), 2.0);
    }
    // A scaled residual r leaves T_out uncertain by about r times the film's temperature rise.
    const double bound = 10.0 * tolerance * (T_out[0] - m.T_in);
    std::printf("k = %.0e W/(m K): |T_out(Newton) - T_out(marching)| = %.2e K (tolerance 10 x tolerance applied x "
                "rise = %.2e K)\n",
                k, std::abs(T_out[0] - T_out[1]), bound);
    EXPECT_NEAR(T_out[0], T_out[1], bound);
  }
  // At the design point (ZBS bed + mixing, k_n ~ 10 W/(m K)) the round-off level is far
  // below 1e-10: the tolerance applied is the absolute one, so results there do not move.
  FilmModel m = centrec_model();
  FilmOperator op(analytic_film(centrec_film()), m, FilmGridSpec{});
  op.freeze_inputs(true);
  const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), SteadySettings{});
  std::printf("design point (ZBS + mixing): round-off level %.3g, tolerance applied %.3g (absolute 1e-10)\n",
              r.residual_floor, r.tolerance);
  EXPECT_EQ(r.tolerance, 1e-10);
}
