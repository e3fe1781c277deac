// The thermal steady solve cannot hang and accepts a valid case at the edge
// (docs/reliability.md): a film without flux converges (its residual scaled by the power
// the flow can lose, not by a 1 K rise, which asked for less than round-off); a film
// heated far beyond any physical temperature is stopped by the wall-time budget with a
// message saying so.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <fstream>
#include <iterator>
#include <string>

#include "config/case_thermal.hpp"
#include "runs/thermal_case_run.hpp"
#include "tests/test_case_dir.hpp"
#include "thermal/cvode_integrator.hpp"

using namespace centrec;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

TEST(ThermalLimits, AZeroFluxCaseConverges) {
  const std::string dir = temp_dir("zero_flux");
  // The shipped uniform-flux case without its flux, on a coarser grid.
  std::ifstream in(CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("q_film: 1.0e6"), 13, "q_film: 0");
  text.replace(text.find("{nz: 200, nxi: 40}"), 18, "{nz: 100, nxi: 20}");
  const config::ThermalCase c = config::read_thermal_case(write_case(dir, text));
  const runs::ThermalRun r = runs::run_thermal_case(c);
  EXPECT_LE(r.steady.residual, c.steady.tolerance);
  EXPECT_LT(r.balance.T_out, c.model.T_in);  // it only loses heat
  EXPECT_GT(r.balance.T_out, c.model.T_in - 50.0);
}

TEST(ThermalLimits, AFilmThatCannotReachASteadyStateIsRefusedOrStopped) {
  // 20 MW/m2 on a film that hardly moves, with no loss: it would heat without bound.
  const std::string dir = temp_dir("stiff");
  const std::string stiff = R"(title: stiff
film:
  analytic: {thickness: 1.3e-3, u_surface: 1.0e-6}
thermal:
  T_in: 873.15
  flux: {q_film: 2.0e7}
  radiation: {model: open_surface}
  surface: {loss_factor: 0, h_conv: 0}
  wall: {adiabatic: true}
  solver: {max_wall_time: 2}
)";
  // Refused as it is read: all at 5000 K it would still absorb more than it carries and loses.
  try {
    config::read_thermal_case(write_case(dir, stiff));
    ADD_FAILURE() << "a film heated without bound was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("the film has no steady state below 5000 K"), std::string::npos) << e.what();
  }
  // Given to the solver anyway (read without flux, then heated), the wall-time budget stops it.
  std::string cold = stiff;
  cold.replace(cold.find("q_film: 2.0e7"), 13, "q_film: 0");
  config::ThermalCase c = config::read_thermal_case(write_case(dir, cold));
  c.model.flux.q = 2.0e7;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    runs::run_thermal_case(c);
    ADD_FAILURE() << "a film heated without bound reached a steady state";
  } catch (const thermal::SolverError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("no steady state within the wall-time budget of 2 s"), std::string::npos) << msg;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(wall, 30.0);
}

// Without sunlight to speak of the efficiency is not a figure (a flux of 1e-300 W/m2 printed
// an efficiency of -3e298 and a residual of 4e289 "of aperture power"); the balances still
// close against their largest power, the heat the film loses.
TEST(ThermalLimits, AFilmWithoutSunlightHasNoEfficiency) {
  const std::string dir = temp_dir("no_sun");
  std::ifstream in(CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml");
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* q : {"q_film: 1e-300", "q_film: 0"}) {
    std::string text = base;
    text.replace(text.find("q_film: 1.0e6"), 13, q);
    text.replace(text.find("{nz: 200, nxi: 40}"), 18, "{nz: 100, nxi: 20}");
    const runs::ThermalRun r = runs::run_thermal_case(config::read_thermal_case(write_case(dir, text)), false);
    const thermal::FilmBalance& b = r.balance;
    std::printf("%s: efficiency %g, receiver residual %.2e of %.4g W, film residual %.2e of %.4g W\n", q, b.efficiency,
                b.receiver_residual / thermal::receiver_balance_scale(b), thermal::receiver_balance_scale(b),
                b.residual / thermal::film_balance_scale(b), thermal::film_balance_scale(b));
    EXPECT_TRUE(std::isnan(b.efficiency)) << q;
    EXPECT_LT(std::fabs(b.receiver_residual), 1e-9 * thermal::receiver_balance_scale(b));
    EXPECT_GT(thermal::receiver_balance_scale(b), 1e4);  // the film's losses, W
  }
}

// A residual above 1e-6 of the balance's largest power stops the run instead of being
// reported (a figure of a solution that does not conserve energy is not a result).
TEST(ThermalLimits, ABalanceThatDoesNotCloseIsAnError) {
  thermal::FilmBalance b;
  b.aperture_power = b.absorbed = 1e4;
  b.carried = 9e3;
  b.emitted = b.emitted_loss = 1e3;
  EXPECT_NO_THROW(runs::check_balance(b));
  b.receiver_residual = 5e-3;  // 5e-7 of the aperture power
  b.residual = -5e-3;
  EXPECT_NO_THROW(runs::check_balance(b));
  b.receiver_residual = 0.02;
  try {
    runs::check_balance(b);
    ADD_FAILURE() << "a receiver residual of 2e-6 of its aperture power passed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the receiver's energy balance does not close: residual 0.02 W against its "
                                         "largest power 1e+04 W"),
              std::string::npos)
        << e.what();
  }
  b.receiver_residual = 0.0;
  b.residual = std::nan("");
  EXPECT_THROW(runs::check_balance(b), std::runtime_error);
}
