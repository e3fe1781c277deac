// Transients with the same integrator: a 10x flux step, a passing cloud and a
// halving of the mass flow integrate without solver failure and settle on the steady state
// of the new operating point. Impossible settings give clear errors, not crashes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "film_test_cases.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"
#include "thermal/transient_run.hpp"

using namespace centrec::thermal;
using namespace centrec::thermal::testcases;

namespace {
double steady_T_out(const AnalyticFilm& a, const FilmModel& m) {
  FilmOperator op(analytic_film(a), m, small_grid());
  op.freeze_inputs(true);
  const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), SteadySettings{});
  return op.balance(0.0, r.y.data()).T_out;
}

TransientResult run(const AnalyticFilm& a, const FilmModel& m, double t_end,
                    LinearSolver solver = LinearSolver::band) {
  FilmOperator op(analytic_film(a), m, small_grid());
  op.freeze_inputs(true);
  const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), SteadySettings{});
  TransientSettings s;
  s.t_end = t_end;
  s.n_outputs = 81;
  s.integrator.linear_solver = solver;
  return run_transient(op, r.y, s);
}
// 0.1 MW/m2, stepping to 1 MW/m2 at t = 2 s.
FilmModel tenfold_flux_step() {
  FilmModel m = centrec_model();
  m.flux.q = 1e5;
  m.flux_time.kind = TimeFactor::Kind::step;
  m.flux_time.level = 10.0;
  m.flux_time.t_start = 2.0;
  return m;
}
}  // namespace

TEST(FilmTransients, TenfoldFluxStepSettlesOnNewSteadyState) {
  const FilmModel m = tenfold_flux_step();
  const TransientResult r = run(centrec_film(), m, 80.0);
  FilmModel after = m;
  after.flux.q = 1e6;
  after.flux_time = TimeFactor{};
  const double target = steady_T_out(centrec_film(), after);
  const double end = r.samples.back().balance.T_out;
  std::printf("10x flux step: T_out %.2f -> %.2f K after 78 s; steady at the new flux %.2f K; |diff| %.3f K "
              "(tolerance 0.5 K); %ld steps, %ld Newton iterations\n",
              r.samples.front().balance.T_out, end, target, std::abs(end - target), r.stats.steps,
              r.stats.newton_iterations);
  EXPECT_NEAR(end, target, 0.5);
}

TEST(FilmTransients, KluSparseSolverMatchesBand) {
  const FilmModel m = tenfold_flux_step();
  const TransientResult band = run(centrec_film(), m, 20.0, LinearSolver::band);
  const TransientResult klu = run(centrec_film(), m, 20.0, LinearSolver::klu);
  double diff = 0.0;
  for (std::size_t k = 0; k < band.samples.size(); ++k)
    diff = std::max(diff, std::abs(band.samples[k].balance.T_out - klu.samples[k].balance.T_out));
  std::printf("flux step with KLU vs band: max |T_out difference| over 81 samples %.2e K (tolerance 0.01 K, "
              "i.e. within the integration tolerance); steps %ld vs %ld\n",
              diff, klu.stats.steps, band.stats.steps);
  EXPECT_LT(diff, 0.01);
}

TEST(FilmTransients, CloudPassageRecovers) {
  FilmModel m = centrec_model();
  m.flux_time.kind = TimeFactor::Kind::pulse;
  m.flux_time.level = 0.1;
  m.flux_time.t_start = 2.0;
  m.flux_time.t_end = 8.0;
  m.flux_time.ramp = 1.0;
  const TransientResult r = run(centrec_film(), m, 80.0);
  double T_min = 1e9;
  for (const auto& s : r.samples) T_min = std::min(T_min, s.balance.T_out);
  const double start = r.samples.front().balance.T_out, end = r.samples.back().balance.T_out;
  std::printf("cloud (flux x0.1 from 2 to 8 s): T_out %.2f K, dips to %.2f K, back to %.2f K; |end - start| %.3f K "
              "(tolerance 0.5 K)\n",
              start, T_min, end, std::abs(end - start));
  EXPECT_LT(T_min, start - 50.0);
  EXPECT_NEAR(end, start, 0.5);
}

TEST(FilmTransients, MassFlowHalvingSettlesOnNewSteadyState) {
  FilmModel m = centrec_model();
  m.flux.q = 5e5;
  m.flow_time.kind = TimeFactor::Kind::step;
  m.flow_time.level = 0.5;
  m.flow_time.t_start = 2.0;
  m.flow_time.ramp = 0.5;
  // Dispersion fixed (not tied to the shear rate) so that halving u_surface in the analytic
  // film is exactly the velocity factor 0.5 (the factor scales u only).
  AnalyticFilm a = centrec_film();
  a.D_shear_coeff = 0.0;
  a.D_uniform = 4e-6;
  const TransientResult r = run(a, m, 120.0);
  AnalyticFilm half = a;
  half.u_surface *= 0.5;  // the velocity factor scales every mass flux linearly
  FilmModel after = m;
  after.flow_time = TimeFactor{};
  const double target = steady_T_out(half, after);
  const double end = r.samples.back().balance.T_out;
  std::printf("mass flow x0.5: T_out %.2f -> %.2f K; steady at half flow %.2f K; |diff| %.3f K (tolerance 0.5 K)\n",
              r.samples.front().balance.T_out, end, target, std::abs(end - target));
  EXPECT_NEAR(end, target, 0.5);
}

TEST(FilmErrors, ImpossibleSettingsGiveClearErrors) {
  auto message = [](auto f) {
    try {
      f();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  IntegratorSettings tight;
  tight.rtol = 1e-30;
  const std::string e1 = message([&] { tight.check(); });
  AnalyticFilm neg = centrec_film();
  neg.thickness = -1e-3;
  const std::string e2 = message([&] { analytic_film(neg); });
  FilmGridSpec one = small_grid();
  one.nz = 1;
  const std::string e3 = message([&] { FilmOperator op(analytic_film(centrec_film()), centrec_model(), one); });
  FilmModel unsorted = centrec_model();
  unsorted.flux.kind = FluxProfile::Kind::table;
  unsorted.flux.table_z = {0.0, 0.5, 0.4};
  unsorted.flux.table_q = {1e5, 1e5, 1e5};
  const std::string e4 = message([&] { FilmOperator op(analytic_film(centrec_film()), unsorted, small_grid()); });
  // A CVODE failure: far too few steps allowed for a long transient.
  FilmModel m = centrec_model();
  m.flux_time.kind = TimeFactor::Kind::step;
  m.flux_time.level = 10.0;
  FilmOperator op(analytic_film(centrec_film()), m, small_grid());
  TransientSettings ts;
  ts.t_end = 50.0;
  ts.n_outputs = 2;
  ts.integrator.max_steps = 3;
  const std::string e5 = message([&] { run_transient(op, op.uniform_state(m.T_in), ts); });
  for (const auto& e : {e1, e2, e3, e4, e5}) std::printf("error: %s\n", e.c_str());
  EXPECT_NE(e1.find("relative tolerance"), std::string::npos);
  EXPECT_NE(e2.find("thickness"), std::string::npos);
  EXPECT_NE(e3.find("nz"), std::string::npos);
  EXPECT_NE(e4.find("increase"), std::string::npos);
  EXPECT_NE(e5.find("CV_TOO_MUCH_WORK"), std::string::npos);
  EXPECT_NE(e5.find("t = "), std::string::npos);
}
