#include "runs/thermal_case_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace centrec::runs {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void check_balance(const thermal::FilmBalance& b) {
  const struct {
    const char* what;
    double residual, scale;
  } balances[] = {{"film", b.residual, thermal::film_balance_scale(b)},
                  {"receiver", b.receiver_residual, thermal::receiver_balance_scale(b)}};
  for (const auto& x : balances)
    if (!(std::fabs(x.residual) <= thermal::kBalanceTolerance * x.scale)) {
      char why[400];
      std::snprintf(why, sizeof why,
                    "the %s's energy balance does not close: residual %.3g W against its largest power %.3g W "
                    "(more than %.0e of it); the solution is not a result",
                    x.what, x.residual, x.scale, thermal::kBalanceTolerance);
      throw std::runtime_error(why);
    }
}

ThermalRun run_thermal_case(const config::ThermalCase& c, bool report) {
  ThermalRun r;
  r.op = std::make_unique<thermal::FilmOperator>(c.film, c.model, c.grid);
  thermal::FilmOperator& op = *r.op;
  op.freeze_inputs(true);
  if (report)
    std::fprintf(stderr, "thermal: steady film energy equation on %d x %d cells (CVODE, then Newton)\n", op.grid().nz,
                 op.grid().nxi);
  const auto t0 = std::chrono::steady_clock::now();
  r.steady = thermal::solve_steady(op, op.uniform_state(c.model.T_in), c.steady);
  r.steady_seconds = since(t0);
  if (report) std::fprintf(stderr, "thermal: steady state in %.2f s\n", r.steady_seconds);
  r.balance = op.balance(0.0, r.steady.y.data());
  check_balance(r.balance);
  r.fields = op.fields(0.0, r.steady.y.data());
  r.keff = op.keff_sections(r.steady.y.data());
  if (c.transient) {
    const auto t1 = std::chrono::steady_clock::now();
    if (report) std::fprintf(stderr, "thermal: transient from the steady state\n");
    r.transient = thermal::run_transient(op, r.steady.y, c.transient_settings);
    r.transient_seconds = since(t1);
    r.has_transient = true;
  }
  return r;
}

}  // namespace centrec::runs
