// Speed vs accuracy of the thermal film solver (docs/architecture.md): the
// outlet-temperature error against a very fine reference vs wall time, over grid sizes,
// steady tolerances, 1D vs 2D and upwind vs van Leer advection, for two operating points:
// the CentRec film with shear mixing (k_eff ~ 10 W/(m K)) and the same film without mixing
// (conduction only, strong surface overheating). Writes CSV to stdout; plot with
// tests/thermal/bench/plot_bench_thermal.py. Built, never run by ctest.
// Usage: bench_thermal_accuracy [--quick] > bench.csv
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "thermal/analytic_film.hpp"
#include "thermal/film_operator.hpp"
#include "thermal/steady_state.hpp"

using namespace centrec::thermal;

namespace {
struct Point {
  double T_out, seconds;
};

FilmModel model() {
  FilmModel m;
  m.flux.q = 1.0e6;
  m.surface.h_conv = 10.0;
  m.wall.U_w = 1.0;
  m.T_in = 873.15;
  return m;
}

AnalyticFilm film(bool mixing) {
  AnalyticFilm a;
  a.thickness = 6e-3;
  a.u_surface = 0.26;
  a.phi = 0.55;
  a.D_shear_coeff = mixing ? 0.05 : 0.0;
  return a;
}

// Best of `repeat` wall times of a full steady solve (operator set-up included).
Point solve(bool mixing, FilmGridSpec spec, double tol, bool newton_first, int repeat) {
  Point p{0.0, 1e300};
  for (int k = 0; k < repeat; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    FilmModel m = model();
    m.conductivity.mixing = mixing;
    FilmOperator op(analytic_film(film(mixing)), m, spec);
    op.freeze_inputs(true);
    SteadySettings s;
    s.tolerance = tol;
    s.newton_first = newton_first;
    const SteadyResult r = solve_steady(op, op.uniform_state(m.T_in), s);
    const double T = op.balance(0.0, r.y.data()).T_out;
    p.seconds = std::min(p.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    p.T_out = T;
  }
  return p;
}

FilmGridSpec grid(int nz, int nxi, Advection adv, bool lumped = false) {
  FilmGridSpec g;
  g.nz = nz;
  g.nxi = nxi;
  g.advection = adv;
  g.lumped = lumped;
  return g;
}
}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf("case,method,nz,nxi,steady_tolerance,T_out_K,error_K,wall_s\n");
  for (bool mixing : {true, false}) {
    const char* name = mixing ? "with_mixing" : "no_mixing";
    // Reference: van Leer on the finest grid (the wall-normal direction needs the finer
    // refinement: without mixing the heated surface layer is thin), with the difference to
    // the grid half as fine in xi as an estimate of its own error.
    const int rz = quick ? 200 : 400, rx = quick ? 80 : 160;
    const Point ref = solve(mixing, grid(rz, rx, Advection::van_leer), 1e-11, true, 1);
    const Point half = solve(mixing, grid(rz, rx / 2, Advection::van_leer), 1e-11, true, 1);
    std::fprintf(stderr, "%s: reference T_out %.6f K (%dx%d van Leer, %.1f s); nxi/2 differs by %.4f K\n", name,
                 ref.T_out, rz, rx, ref.seconds, half.T_out - ref.T_out);
    auto row = [&](const char* method, const FilmGridSpec& g, double tol, const Point& p) {
      std::printf("%s,%s,%d,%d,%.0e,%.6f,%.6f,%.6f\n", name, method, g.nz, g.lumped ? 1 : g.nxi, tol, p.T_out,
                  std::abs(p.T_out - ref.T_out), p.seconds);
      std::fflush(stdout);
    };
    const int sizes[][2] = {{25, 6}, {50, 10}, {100, 20}, {200, 40}, {400, 40}, {200, 80}};
    for (const auto& sz : sizes) {
      for (Advection adv : {Advection::upwind, Advection::van_leer}) {
        const FilmGridSpec g = grid(sz[0], sz[1], adv);
        row(adv == Advection::upwind ? "2D upwind" : "2D van Leer", g, 1e-10, solve(mixing, g, 1e-10, true, 3));
      }
    }
    for (int nz : {25, 50, 100, 200, 400, 1600}) {
      for (Advection adv : {Advection::upwind, Advection::van_leer}) {
        const FilmGridSpec g = grid(nz, 1, adv, true);
        row(adv == Advection::upwind ? "1D upwind" : "1D van Leer", g, 1e-10, solve(mixing, g, 1e-10, true, 3));
      }
    }
    for (double tol : {1e-2, 1e-4, 1e-6, 1e-10}) {
      const FilmGridSpec g = grid(200, 40, Advection::upwind);
      row("2D upwind 200x40 newton-first", g, tol, solve(mixing, g, tol, true, 3));
      row("2D upwind 200x40 marching-only", g, tol, solve(mixing, g, tol, false, 1));
    }
  }
  return 0;
}
