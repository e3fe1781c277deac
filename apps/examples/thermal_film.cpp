// A thermal film on an analytic field through the thermal library's API
// (thermal/film_operator.hpp, steady_state.hpp; docs/thermal_model.md).
//
// A film of bauxite particles 6 mm thick flows along a 1 m drum under a uniform
// concentrated flux. With every loss switched off (no emission, no convection, an adiabatic
// wall, no axial conduction back through the inlet) and a constant c_p, the energy balance
// fixes the outlet temperature:
//     mdot c_p (T_out - T_in) = alpha q pi D L.
// The program solves the film's steady temperature field and checks that its mixing-cup
// outlet temperature equals that value within 1e-6 K, and that the film's mass flow equals
// the closed form of its velocity profile. It prints one line per check and exits with 1
// if one fails.
//
// Build: part of the default build (build/apps/examples/example_thermal_film); ctest runs it
// (test example_thermal_film, label default).
#include <cmath>
#include <cstdio>

#include "thermal/analytic_film.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;

int main() {
  // 1. The film field: thickness t, solid fraction phi, axial velocity 0 within one particle
  //    diameter d of the wall and linear from there to u_surface at the free surface.
  AnalyticFilm a;
  a.thickness = 6e-3;       // m
  a.u_surface = 0.26;       // m/s
  a.phi = 0.55;
  a.d = 1.2e-3;             // m
  a.drum_diameter = 1.0;    // m
  a.length = 1.0;           // m
  const FilmField film = analytic_film(a);

  // 2. The model: material, constant c_p, uniform flux, inlet temperature, and no losses.
  FilmModel m;
  m.heat.cp_constant = 1200.0;  // J/(kg K); 0 would select bauxite's c_p(T)
  m.flux.kind = FluxProfile::Kind::uniform;
  m.flux.q = 1.0e6;             // W/m2 on the film surface
  m.T_in = 873.15;              // K
  m.surface.loss_factor = 0.0;  // no emission (open-surface model with F = 0)
  m.surface.h_conv = 0.0;       // no convection
  m.wall.adiabatic = true;      // nothing through the drum wall
  m.conductivity.axial = ConductivitySettings::Axial::none;  // nothing conducted back out of the inlet

  // 3. The grid: 100 axial cells, 20 across the depth (xi = eta / t).
  FilmGridSpec grid;
  grid.nz = 100;
  grid.nxi = 20;

  // 4. The operator (finite volumes as an ODE system) and its steady state, from a film
  //    uniformly at the inlet temperature. freeze_inputs: the flux at t = 0 throughout.
  FilmOperator op(film, m, grid);
  op.freeze_inputs(true);
  const SteadyResult steady = solve_steady(op, op.uniform_state(m.T_in), SteadySettings{});
  const FilmBalance b = op.balance(0.0, steady.y.data());
  std::printf("thermal film: steady residual %.2e after %d Newton iterations; absorbed %.6g W, carried %.6g W\n",
              steady.residual, steady.newton_iterations, b.absorbed, b.carried);

  // 5. The energy balance by hand: mass flow of the profile of step 1 round the drum,
  //    rho_s phi pi D u_surface (t - d) / 2, and the absorbed power alpha q pi D L.
  const double mdot = m.material.rho_s * a.phi * M_PI * a.drum_diameter * a.u_surface * (a.thickness - a.d) / 2.0;
  const double absorbed = m.material.alpha * m.flux.q * M_PI * a.drum_diameter * a.length;
  const double T_balance = m.T_in + absorbed / (mdot * m.heat.cp_constant);

  // 6. Compare.
  const double flow_error = std::fabs(b.mass_flow - mdot) / mdot;
  const double T_error = std::fabs(b.T_out - T_balance);
  const bool flow_ok = flow_error < 1e-9, T_ok = T_error < 1e-6;
  std::printf("mass flow %.9g kg/s, closed form %.9g kg/s: relative difference %.1e (expected < 1e-9): %s\n",
              b.mass_flow, mdot, flow_error, flow_ok ? "agree" : "DIFFER");
  std::printf("outlet temperature %.6f K, energy balance %.6f K (rise %.2f K): difference %.1e K (expected < 1e-6 K): "
              "%s\n",
              b.T_out, T_balance, T_balance - m.T_in, T_error, T_ok ? "agree" : "DIFFER");
  return flow_ok && T_ok ? 0 : 1;
}
