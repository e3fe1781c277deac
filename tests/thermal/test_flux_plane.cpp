// Where the solar flux of a case is given (docs/thermal_model.md, "Surface and solar
// absorption"; docs/cavity_model.md, "Two bands"). `flux.q_film` is the sunlight's first
// incidence on the film (what the former `flux.q` meant); `flux.q_aperture` is the mean flux
// through the aperture of the cavity. Checks, each against a hand calculation:
//   - the former keys `q`, `q_peak`, `q_base` are refused with a message naming the new key;
//   - q_aperture gives aperture power = q_aperture x pi r_a^2 (relative 1e-12) and the film
//     flux q_aperture x A_aperture / A_film;
//   - a case given by q_aperture and the same case given by the q_film it implies solve to the
//     same outlet temperature (1e-9 K): one physical input, two ways of writing it;
//   - q_aperture on the open-surface model (no aperture) is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "config/case_thermal.hpp"
#include "runs/thermal_case_run.hpp"
#include "tests/test_case_dir.hpp"

using namespace centrec;
using namespace centrec::config;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

namespace {
constexpr double kPi = 3.14159265358979323846;

std::string case_text(const std::string& flux, const std::string& radiation = "{model: cavity, aperture_diameter: 0.7}") {
  return "title: flux plane\n"
         "film:\n"
         "  analytic: {thickness: 6.0e-3, u_surface: 0.26, phi: 0.55, D_shear_coeff: 0.05, drum_diameter: 1.0, length: 1.0}\n"
         "thermal:\n"
         "  grid: {nz: 40, nxi: 12}\n"
         "  T_in: 873.15\n"
         "  flux: " + flux + "\n"
         "  radiation: " + radiation + "\n";
}

std::string config_error(const std::string& dir, const std::string& text) {
  try {
    read_thermal_case(write_case(dir, text));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(FluxPlane, FormerKeysAreRefusedNamingTheNewOnes) {
  const std::string dir = temp_dir("flux_old_keys");
  const std::string q = config_error(dir, case_text("{profile: uniform, q: 2.0e5}"));
  const std::string peak = config_error(dir, case_text("{profile: gaussian, q_peak: 1.5e6, z_center: 0.5, sigma: 0.2}"));
  const std::string base = config_error(
      dir, case_text("{profile: gaussian, q_film_peak: 1.5e6, q_base: 1.0e5, z_center: 0.5, sigma: 0.2}"));
  for (const auto& e : {q, peak, base}) std::printf("error: %s\n", e.c_str());
  EXPECT_NE(q.find("thermal.flux.q"), std::string::npos);
  EXPECT_NE(q.find("q_film"), std::string::npos);
  EXPECT_NE(q.find("q_aperture"), std::string::npos);
  EXPECT_NE(peak.find("q_film_peak"), std::string::npos);
  EXPECT_NE(base.find("q_film_base"), std::string::npos);
}

TEST(FluxPlane, ApertureFluxGivesItsPowerAndTheSameStateAsTheFilmFluxItImplies) {
  const std::string dir = temp_dir("flux_aperture");
  const double q_ap = 1.0e6, d_ap = 0.7, D = 1.0, L = 1.0;
  const ThermalCase by_aperture = read_thermal_case(write_case(dir, case_text("{profile: uniform, q_aperture: 1.0e6}")));
  const runs::ThermalRun a = runs::run_thermal_case(by_aperture);
  const double A_ap = kPi * d_ap * d_ap / 4.0, A_film = kPi * D * L;
  const double expected_power = q_ap * A_ap, expected_film = q_ap * A_ap / A_film;
  std::printf("aperture power %.9g W, expected q_aperture x A_aperture = %.9g W (relative %.2e, tolerance 1e-12)\n",
              a.balance.aperture_power, expected_power, a.balance.aperture_power / expected_power - 1.0);
  EXPECT_NEAR(a.balance.aperture_power / expected_power, 1.0, 1e-12);
  std::printf("film flux %.9g W/m2, expected %.9g W/m2; operator areas: film %.9g m2, aperture %.9g m2\n",
              a.op->model().flux.q, expected_film, a.op->film_area(), a.op->aperture_area());
  EXPECT_NEAR(a.op->model().flux.q / expected_film, 1.0, 1e-12);
  EXPECT_NEAR(a.op->film_area(), A_film, 1e-12);
  EXPECT_NEAR(a.op->aperture_area(), A_ap, 1e-12);

  char film_flux[96];
  std::snprintf(film_flux, sizeof film_flux, "{profile: uniform, q_film: %.17g}", expected_film);
  const runs::ThermalRun f = runs::run_thermal_case(read_thermal_case(write_case(dir, case_text(film_flux))));
  std::printf("T_out by q_aperture %.10f K, by q_film %.10f K (|diff| %.2e K, tolerance 1e-9 K)\n", a.balance.T_out,
              f.balance.T_out, std::abs(a.balance.T_out - f.balance.T_out));
  EXPECT_NEAR(a.balance.T_out, f.balance.T_out, 1e-9);
  EXPECT_GT(a.balance.T_out, by_aperture.model.T_in + 10.0);  // the flux does heat the film
}

TEST(FluxPlane, ApertureFluxNeedsTheCavityModel) {
  const std::string dir = temp_dir("flux_open");
  const std::string e = config_error(dir, case_text("{profile: uniform, q_aperture: 1.0e6}", "{model: open_surface}"));
  const std::string both = config_error(dir, case_text("{profile: uniform, q_film: 1.0e5, q_aperture: 1.0e6}"));
  std::printf("error: %s\nerror: %s\n", e.c_str(), both.c_str());
  EXPECT_NE(e.find("q_aperture"), std::string::npos);
  EXPECT_NE(e.find("cavity"), std::string::npos);
  EXPECT_NE(both.find("exactly one"), std::string::npos);
}
