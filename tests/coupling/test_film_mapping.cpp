// Mapping DEM averages onto the thermal film: the mapped film
// carries the DEM's mass flow (independent quadrature and the thermal grid, 1 %), the
// tangential average weights the zones, empty bins are filled, the glued wall layer is
// added back with its exact volume, and the scaled-up film equals the scaled-down one in
// particle diameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling/film_mapping.hpp"
#include "coupling/film_mass_flow.hpp"
#include "coupling/film_scale_up.hpp"
#include "coupling/glued_layer.hpp"
#include "synthetic_dem_film.hpp"
#include "thermal/film_grid.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec;

namespace {
// 2 pi rho integral phi u (R - eta) d eta by the midpoint rule on FilmField::sample: an
// independent check of the exact piecewise integrals.
double quadrature_mass_flow(const thermal::FilmField& f, std::size_t i, double rho, double R) {
  const int n = 20000;
  const double t = f.t[i], h = t / n;
  double s = 0.0;
  for (int k = 0; k < n; ++k) {
    const double e = (k + 0.5) * h;
    s += f.sample(f.phi, f.z[i], e) * f.sample(f.u, f.z[i], e) * (R - e) * h;
  }
  return 2.0 * M_PI * rho * s;
}
}  // namespace

TEST(FilmMapping, MappedFilmCarriesTheDemMassFlow) {
  const auto a = test::synthetic_dem_film(0.12);
  auto mapped = coupling::map_dem_film(a);
  thermal::FilmField f = mapped.film;
  const auto c = coupling::conserve_mass_flow(f, a.particle_density, a.mdot);
  double worst = 0.0;
  for (std::size_t i = 0; i < f.nz(); ++i)
    worst = std::max(worst, std::abs(quadrature_mass_flow(f, i, a.particle_density, a.drum_radius) / a.mdot - 1.0));
  std::printf("cylindrical mass flow vs DEM mdot: worst section error %.2e (tolerance 1e-2); planar D %.5f m\n",
              worst, c.planar_diameter);
  EXPECT_LT(worst, 1e-2);
  EXPECT_LT(c.max_cylindrical_error, 1e-2);
  // The thermal model's own mass flow (its grid integrates the field exactly).
  thermal::FilmGridSpec spec;
  spec.nz = 50, spec.nxi = 16;
  const auto g = thermal::build_film_grid(f, spec, a.particle_density);
  const double thermal_mdot = g.mass_flux * g.perimeter;
  std::printf("thermal grid mass flow %.6g kg/s vs DEM %.6g kg/s (tolerance 1 %%)\n", thermal_mdot, a.mdot);
  EXPECT_NEAR(thermal_mdot / a.mdot, 1.0, 1e-2);
  // Before scaling, the profile carried a different flux; the record says how much.
  EXPECT_EQ(c.sampled_over_mdot.size(), f.nz());
  EXPECT_GT(std::abs(c.sampled_over_mdot[0] - 1.0), 1e-3);
}

TEST(FilmMapping, TangentialAverageWeightsTheZones) {
  auto a = test::synthetic_dem_film(0.12);
  for (std::size_t b = 18; b < 36; ++b) a.surface_velocity[b] = 0.0, a.moving_zone_of_bin[b] = 0;
  const auto m = coupling::map_dem_film(a);
  std::printf("moving fraction %.3f, velocity factor %.3f (expected 0.5, 0.5)\n", m.tangential.moving_fraction,
              m.tangential.velocity_factor);
  EXPECT_DOUBLE_EQ(m.tangential.moving_fraction, 0.5);
  EXPECT_DOUBLE_EQ(m.tangential.velocity_factor, 0.5);
  const auto& f = m.film;
  const double d = a.particle_diameter;
  // Section 0 lies below the first profile level (z/L = 0.3): that level's profile, held.
  const double eta = 3.25 * d;
  EXPECT_NEAR(f.sample(f.u, f.z[0], eta), 0.5 * 0.1 * 2.25 * 1.06, 1e-12);
  EXPECT_NEAR(f.sample(f.phi, f.z[0], eta), 0.54, 1e-12);
  // Midway between the levels 0.3 and 0.5 the profile is interpolated linearly.
  EXPECT_NEAR(f.sample(f.u, 0.4 * a.length, eta), 0.5 * 0.1 * 2.25 * 1.08, 1e-12);
}

TEST(FilmMapping, EmptyBinsAreFilled) {
  auto a = test::synthetic_dem_film(0.12);
  for (auto& row : a.u_turns)
    for (std::size_t k : {0u, 1u, 12u, 13u, 14u, 15u}) row[k] = 0.0;
  for (std::size_t k : {0u, 14u, 15u}) a.phi_moving[k] = a.phi_stationary[k] = 0.0;
  const auto m = coupling::map_dem_film(a);
  const auto& f = m.film;
  const double d = a.particle_diameter;
  EXPECT_GT(m.tangential.filled_bins, 0);
  EXPECT_EQ(f.sample(f.u, f.z[0], 0.25 * d), 0.0);                          // wall side: at rest
  EXPECT_NEAR(f.sample(f.u, f.z[0], 7.75 * d), 0.1 * 4.75 * 1.06, 1e-12);  // top: last sampled value
  EXPECT_NEAR(f.sample(f.phi, f.z[0], 0.25 * d), 0.52, 1e-12);               // nearest sampled bin
}

TEST(FilmMapping, AZoneTheDemNeverSawHasNoWeight) {
  // The whole circumference moving: the stationary-zone profiles are NaN (no bin sampled).
  auto a = test::synthetic_dem_film(0.12);
  a.phi_stationary.assign(16, std::nan(""));
  a.phi_stationary_std.assign(16, std::nan(""));
  const auto m = coupling::map_dem_film(a);
  EXPECT_DOUBLE_EQ(m.tangential.moving_fraction, 1.0);
  EXPECT_NEAR(m.film.sample(m.film.phi, m.film.z[0], 2.25 * a.particle_diameter), 0.52, 1e-12);
}

TEST(FilmMapping, GluedLayerVolumeIsExact) {
  const double d = 1.2e-3, per_area = 1.0 / (d * d);  // square lattice, spacing 1 d
  std::vector<double> centres;
  for (int k = 0; k < 16; ++k) centres.push_back(0.25 + 0.5 * k);
  const auto phi = coupling::glued_layer_solid_fraction(centres, 0.5, d, d, per_area);
  double volume = 0.0;
  for (double p : phi) volume += p * 0.5 * d;
  const double exact = per_area * M_PI * d * d * d / 6.0;
  std::printf("glued layer: integral phi d eta %.6e m vs spheres %.6e m; bins 0/1 %.4f/%.4f\n", volume, exact,
              phi[0], phi[1]);
  EXPECT_NEAR(volume / exact, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(phi[2], 0.0);
  EXPECT_NEAR(phi[0], phi[1], 1e-12);  // symmetric about the centre at 0.5 d
}

TEST(FilmMapping, ScaledUpFilmEqualsScaledDownInParticleDiameters) {
  const auto sim = test::synthetic_dem_film(0.03);
  const auto big = test::synthetic_dem_film(1.0);  // the receiver's operating point by eqs 1-3
  const coupling::ReceiverOperatingPoint act{2 * big.drum_radius, big.length, big.omega, big.mdot};
  const auto mapped = coupling::map_dem_film(sim);
  coupling::ScaleUpRecord rec;
  const coupling::ReceiverOperatingPoint dem_drum{2 * sim.drum_radius, sim.length, sim.omega, sim.mdot};
  const auto up = coupling::scale_up_film(mapped.film, dem_drum, act, &rec);
  const double d = sim.particle_diameter;
  std::printf("scale-up: z x %.4f, eq 1/2/3 deviations %.1e/%.1e/%.1e\n", rec.length_ratio, rec.eq1_error,
              rec.eq2_error, rec.eq3_error);
  EXPECT_NEAR(rec.length_ratio, 1.0 / 0.03, 1e-12);
  EXPECT_LT(std::abs(rec.eq1_error) + std::abs(rec.eq2_error) + std::abs(rec.eq3_error), 1e-9);
  ASSERT_EQ(up.nz(), mapped.film.nz());
  for (std::size_t i = 0; i < up.nz(); ++i) {
    EXPECT_NEAR(up.z[i] / up.length, mapped.film.z[i] / mapped.film.length, 1e-14);
    EXPECT_DOUBLE_EQ(up.t[i] / d, mapped.film.t[i] / d);
  }
  EXPECT_EQ(up.eta, mapped.film.eta);
  EXPECT_EQ(up.u, mapped.film.u);
  EXPECT_EQ(up.phi, mapped.film.phi);
  EXPECT_EQ(up.D, mapped.film.D);
  EXPECT_DOUBLE_EQ(up.drum_diameter, 1.0);
  // Imposing each drum's mdot: eq (2) keeps mdot / R, but the film's flux is carried at the
  // mean radius R - eta_bar, so u differs by (R_act/R_sim) (R_sim - eta_bar)/(R_act - eta_bar):
  // the curvature error of the scaling laws at this D/d.
  thermal::FilmField fs = mapped.film, fu = up;
  coupling::conserve_mass_flow(fs, sim.particle_density, sim.mdot);
  coupling::conserve_mass_flow(fu, sim.particle_density, act.mass_flow);
  const std::size_t k = fs.neta() / 2;
  const double ratio = fu.u[k] / fs.u[k], rs = sim.drum_radius, ra = big.drum_radius;
  const double e = coupling::phi_u_eta_integral(fs, 0) / coupling::phi_u_integral(fs, 0);  // section 0's eta_bar
  const double expected = (ra / rs) * (rs - e) / (ra - e);
  std::printf("u after conservation, receiver / DEM drum (D/d = 25): %.4f, expected %.4f (eta_bar = %.2f d)\n", ratio,
              expected, e / d);
  EXPECT_NEAR(ratio, expected, 1e-9);
}

TEST(FilmMapping, MappedFilmRunsTheThermalModelIn1DAnd2D) {
  const auto a = test::synthetic_dem_film(0.12);
  thermal::FilmField f = coupling::map_dem_film(a).film;
  coupling::conserve_mass_flow(f, a.particle_density, a.mdot);
  for (bool lumped : {false, true}) {
    thermal::FilmModel model;
    model.flux.q = 2e5;
    thermal::FilmGridSpec spec;
    spec.nz = 40, spec.nxi = 10, spec.lumped = lumped;
    thermal::FilmOperator op(f, model, spec);
    op.freeze_inputs(true);
    const auto s = thermal::solve_steady(op, op.uniform_state(model.T_in), thermal::SteadySettings{});
    const auto b = op.balance(0.0, s.y.data());
    std::printf("%s: T_out %.2f K, mass flow %.6g kg/s (DEM %.6g)\n", lumped ? "1D" : "2D", b.T_out, b.mass_flow,
                a.mdot);
    EXPECT_NEAR(b.mass_flow / a.mdot, 1.0, 1e-2);
    EXPECT_GT(b.T_out, model.T_in + 10.0);
  }
}
