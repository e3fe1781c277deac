// Near the inlet, a film with the linear velocity profile heated by a constant surface flux
// behaves like a semi-infinite body heated for the contact time z / u_surface:
//   T_s - T_in = 2 alpha q / k sqrt(a tau / pi),  a = k / (rho_s phi c_p)
// Further down, the heat reaches the slower layers and the finite depth, and the surface
// departs from it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "film_test_cases.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;
using namespace centrec::thermal::testcases;

TEST(FilmPenetration, SurfaceFollowsSemiInfiniteSolutionNearInletThenDeparts) {
  AnalyticFilm a;
  a.thickness = 6e-3;
  a.d = 1.2e-3;
  a.u_surface = 0.2;
  a.phi = 0.55;
  a.length = 0.5;
  FilmModel m;
  remove_losses(m);
  m.flux.q = 2e5;
  m.T_in = 500.0;
  m.heat.cp_constant = 1000.0;
  m.conductivity.k_constant = 2.0;
  m.conductivity.mixing = false;
  m.conductivity.axial = ConductivitySettings::Axial::none;  // the semi-infinite solution has none
  FilmGridSpec spec;
  spec.nz = 500;
  spec.nxi = 120;  // resolves the penetration depth (0.2 mm at z = 2 cm) with 4 cells
  FilmOperator op(analytic_film(a), m, spec);
  op.freeze_inputs(true);
  const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), SteadySettings{});
  const ThermalFields f = op.fields(0.0, r.y.data());
  const double rho_c = m.material.rho_s * a.phi * m.heat.cp_constant;
  const double diff = m.conductivity.k_constant / rho_c;
  const double qa = m.material.alpha * m.flux.q;
  auto ratio_at = [&](double z) {
    const int i = static_cast<int>(z / op.grid().dz);
    const double tau = op.grid().zc[i] / a.u_surface;
    const double rise = 2.0 * qa / m.conductivity.k_constant * std::sqrt(diff * tau / M_PI);
    const double depth_ratio = std::sqrt(diff * tau) / (a.thickness - a.d);
    const double ratio = (f.T_surface[i] - m.T_in) / rise;
    std::printf("z = %.3f m: contact time %.3f s, penetration depth / sheared depth %.3f, surface rise %.2f K vs "
                "semi-infinite %.2f K, ratio %.4f\n",
                op.grid().zc[i], tau, depth_ratio, f.T_surface[i] - m.T_in, rise, ratio);
    return ratio;
  };
  const double near = ratio_at(0.02), mid = ratio_at(0.2), far = ratio_at(0.49);
  std::printf("near inlet: |ratio - 1| = %.4f (tolerance 0.03); departure grows downstream: %.3f -> %.3f "
              "(far departure must exceed 0.05)\n",
              std::abs(near - 1.0), mid, far);
  EXPECT_NEAR(near, 1.0, 0.03);
  EXPECT_GT(mid, near);
  EXPECT_GT(far, mid);
  EXPECT_GT(std::abs(far - 1.0), 0.05);
}
