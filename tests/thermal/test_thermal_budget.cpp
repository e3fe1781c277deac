// The error budget end to end (apps/runs/thermal_budget.*, docs/error_budget.md) on a film
// whose outlet temperature is known in closed form: an open surface that neither emits
// (loss factor 0) nor convects (h 0), an adiabatic wall, no axial conduction (nothing leaves
// through the inlet) and a constant c_p. All absorbed sunlight is carried, so
//     T_out = T_in + alpha f_P q A / (mdot c_p s)
// with s the budget's c_p factor and f_P its aperture-power factor. Checks (1e-6 K):
//   - one at a time, the c_p, absorptance and aperture-power ends give that T_out, and the
//     inputs that cannot change it here (k_s, emissivity, convection, Beer-Lambert depth,
//     mixing) leave it where it was;
//   - every Latin hypercube sample gives that T_out for its own drawn values (the draws
//     reach the solver as drawn);
//   - the same seed gives the same samples; the shares add up to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "config/case_thermal.hpp"
#include "runs/thermal_budget.hpp"
#include "tests/test_case_dir.hpp"

using namespace centrec;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

namespace {
const char* kLossless = R"(title: lossless film
film:
  analytic: {thickness: 6.0e-3, u_surface: 0.26, phi: 0.55, D_shear_coeff: 0.05, drum_diameter: 1.0, length: 1.0}
thermal:
  grid: {nz: 30, nxi: 10}
  T_in: 873.15
  heat_capacity: {model: constant, cp: 1200}
  conductivity: {axial: none}
  flux: {q_film: 3.0e5}
  radiation: {model: open_surface}
  surface: {loss_factor: 0.0, h_conv: 0.0}
  wall: {adiabatic: true}
)";

struct Closed {
  double T_in, q, area, mdot, cp;
  double T_out(double alpha, double power, double cp_scale) const {
    return T_in + alpha * power * q * area / (mdot * cp * cp_scale);
  }
};

std::size_t index_of(const runs::BudgetResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.inputs.size(); ++i)
    if (r.inputs[i].name == name) return i;
  ADD_FAILURE() << "no budget input " << name;
  return 0;
}
}  // namespace

TEST(ThermalBudget, LosslessFilmFollowsTheEnergyBalanceInEverySample) {
  const std::string dir = temp_dir("budget_lossless");
  const config::ThermalCase c = config::read_thermal_case(write_case(dir, kLossless));
  runs::BudgetSettings s;
  s.lhs_samples = 12;
  const runs::BudgetResult r = runs::run_thermal_budget(c, s);
  // The analytic film's flow: at rest over the first diameter, linear to u_s at the surface,
  // mdot = rho_s phi u_s (t - d) / 2 x pi D.
  const double A = 3.14159265358979323846 * 1.0 * 1.0, alpha = c.model.material.alpha;
  const double mdot_film = 3560.0 * 0.55 * 0.26 * (6.0e-3 - 1.2e-3) / 2.0 * 3.14159265358979323846 * 1.0;
  const Closed k{c.model.T_in, 3.0e5, A, mdot_film, 1200.0};
  std::printf("nominal T_out %.6f K, closed form %.6f K\n", r.nominal.T_out, k.T_out(alpha, 1.0, 1.0));
  EXPECT_NEAR(r.nominal.T_out, k.T_out(alpha, 1.0, 1.0), 1e-6);
  const std::size_t icp = index_of(r, "c_p"), ia = index_of(r, "absorptance"), ip = index_of(r, "aperture power");
  double worst = 0.0;
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    const auto& in = r.inputs[i];
    auto expected = [&](double v) {
      return k.T_out(i == ia ? v : alpha, i == ip ? v : 1.0, i == icp ? v : 1.0);
    };
    const double e_lo = expected(in.lo), e_hi = expected(in.hi);
    std::printf("%-20s T_out at lo %.6f K (closed form %.6f), at hi %.6f K (closed form %.6f)\n", in.name.c_str(),
                r.per_input[i].at_lo.T_out, e_lo, r.per_input[i].at_hi.T_out, e_hi);
    worst = std::max({worst, std::abs(r.per_input[i].at_lo.T_out - e_lo), std::abs(r.per_input[i].at_hi.T_out - e_hi)});
  }
  for (std::size_t n = 0; n < r.lhs_values.size(); ++n) {
    const auto& v = r.lhs_values[n];
    const double e = k.T_out(v[ia], v[ip], v[icp]);
    worst = std::max(worst, std::abs(r.lhs_outputs[n].T_out - e));
  }
  std::printf("worst |T_out - closed form| over %zu one-at-a-time and %zu hypercube solves: %.2e K (tolerance 1e-6 K)\n",
              2 * r.inputs.size(), r.lhs_values.size(), worst);
  EXPECT_LT(worst, 1e-6);
  // The c_p end must move T_out by the closed form's amount, not by nothing.
  EXPECT_GT(r.per_input[icp].at_lo.T_out - r.nominal.T_out, 5.0);

  double sum_oat = 0.0, sum_lhs = 0.0;
  for (const auto& p : r.per_input) {
    sum_oat += p.share_oat[0];
    sum_lhs += p.share_lhs[0];
  }
  EXPECT_NEAR(sum_oat, 1.0, 1e-12);
  EXPECT_NEAR(sum_lhs, 1.0, 1e-12);
  const runs::BudgetResult again = runs::run_thermal_budget(c, s);
  EXPECT_EQ(again.lhs_values, r.lhs_values);
  for (std::size_t n = 0; n < r.lhs_outputs.size(); ++n) EXPECT_EQ(again.lhs_outputs[n].T_out, r.lhs_outputs[n].T_out);
}

// Inside the cavity every input acts: each moves at least one output at the end of its range
// (an input whose apply were lost would leave all three where they were).
TEST(ThermalBudget, EveryInputMovesAnOutputInTheCavity) {
  const std::string dir = temp_dir("budget_cavity");
  const config::ThermalCase c = config::read_thermal_case(write_case(dir, R"(title: cavity film
film:
  analytic: {thickness: 6.0e-3, u_surface: 0.02015, phi: 0.55, D_shear_coeff: 0.05, drum_diameter: 0.12, length: 0.171}
thermal:
  grid: {nz: 30, nxi: 10}
  T_in: 873.15
  flux: {q_film: 2.0e5}
  radiation: {model: cavity, tilt_deg: 45}
)"));
  const std::vector<runs::BudgetInput> inputs = runs::budget_inputs(c);
  // The particle's four, convection, wind, spillage, Beer-Lambert depth, mixing, film top, aperture power.
  EXPECT_EQ(inputs.size(), 11u);
  const runs::BudgetOutputs nominal = runs::budget_outputs_at(c);
  for (const runs::BudgetInput& in : inputs) {
    config::ThermalCase x = c;
    in.apply(x, in.hi);
    const runs::BudgetOutputs o = runs::budget_outputs_at(x);
    const double moved = std::max({std::abs(o.T_out - nominal.T_out) / nominal.T_out,
                                   std::abs(o.efficiency - nominal.efficiency), std::abs(o.k_eff / nominal.k_eff - 1.0)});
    std::printf("%-20s at %.4g: T_out %+.3f K, efficiency %+.5f, k_eff %+.4f W/(m K)\n", in.name.c_str(), in.hi,
                o.T_out - nominal.T_out, o.efficiency - nominal.efficiency, o.k_eff - nominal.k_eff);
    EXPECT_GT(moved, 1e-5) << in.name;
  }
}

// The film-top row carries the case's thermal.radiation.film_top as its nominal (0 surface,
// 1 two_flux), sets the model at either end, and is left out where two-flux cannot run (a
// depth-lumped film, an open surface whose loss factor is not 1).
TEST(ThermalBudget, FilmTopRowFollowsTheCase) {
  const std::string film =
      "film:\n  analytic: {thickness: 6.0e-3, u_surface: 0.02015, phi: 0.55, D_shear_coeff: 0.05, drum_diameter: 0.12, "
      "length: 0.171}\n";
  auto inputs_of = [&](const std::string& name, const std::string& thermal) {
    const config::ThermalCase c =
        config::read_thermal_case(write_case(temp_dir("budget_film_top_" + name), "title: film top\n" + film + "thermal:\n" + thermal));
    return runs::budget_inputs(c);
  };
  auto film_top = [](const std::vector<runs::BudgetInput>& in) -> const runs::BudgetInput* {
    for (const auto& i : in)
      if (i.name == "film top") return &i;
    return nullptr;
  };
  const auto two = inputs_of("two_flux", "  grid: {nz: 10, nxi: 10}\n  radiation: {model: cavity, film_top: two_flux}\n");
  const auto surf = inputs_of("surface", "  grid: {nz: 10, nxi: 10}\n  radiation: {model: cavity}\n");
  const auto lumped = inputs_of("lumped", "  model: 1d\n  grid: {nz: 10}\n  radiation: {model: cavity}\n");
  const auto lossy = inputs_of("lossy", "  grid: {nz: 10, nxi: 10}\n  radiation: {model: open_surface}\n"
                                        "  surface: {loss_factor: 0.5}\n");
  ASSERT_NE(film_top(two), nullptr);
  ASSERT_NE(film_top(surf), nullptr);
  EXPECT_EQ(film_top(two)->nominal, 1.0);
  EXPECT_EQ(film_top(surf)->nominal, 0.0);
  EXPECT_EQ(film_top(lumped), nullptr);
  EXPECT_EQ(film_top(lossy), nullptr);
  const config::ThermalCase c = config::read_thermal_case(
      write_case(temp_dir("budget_film_top_apply"), "title: film top\n" + film +
                                     "thermal:\n  grid: {nz: 10, nxi: 10}\n  radiation: {model: cavity}\n"));
  config::ThermalCase x = c;
  film_top(surf)->apply(x, film_top(surf)->hi);
  EXPECT_TRUE(x.model.film_top.two_flux);
  film_top(surf)->apply(x, film_top(surf)->lo);
  EXPECT_FALSE(x.model.film_top.two_flux);
}

// The DEM's spread over seeds, read from a `centrec run --replicas` summary, adds to the
// inputs' one-at-a-time sd in quadrature (1e-12); a summary without replicas is refused.
TEST(ThermalBudget, DemReplicaSpreadAddsInQuadrature) {
  const nlohmann::json summary = {
      {"replicas",
       {{"count", 3},
        {"figures",
         {{"/T_out_K", {{"mean", 1115.49}, {"std", 0.02}}},
          {"/efficiency", {{"mean", 0.8979}, {"std", 0.0002}}},
          {"/k_eff/film_mean/k_eff", {{"mean", 0.936}, {"std", 0.008}}}}}}}};
  const runs::ReplicaSpread d = runs::replica_spread_from_summary(summary, "replicas.json");
  runs::BudgetResult r;
  r.oat_sd[0] = 14.38;
  r.oat_sd[1] = 0.0188;
  r.oat_sd[2] = 0.4386;
  runs::add_replica_spread(r, d);
  std::printf("total sd: T_out %.6f K (sqrt(14.38^2 + 0.02^2) = %.6f), k_eff %.6f\n", r.total_sd[0],
              std::hypot(14.38, 0.02), r.total_sd[2]);
  EXPECT_EQ(d.count, 3);
  EXPECT_NEAR(r.total_sd[0], std::hypot(14.38, 0.02), 1e-12);
  EXPECT_NEAR(r.total_sd[1], std::hypot(0.0188, 0.0002), 1e-12);
  EXPECT_NEAR(r.total_sd[2], std::hypot(0.4386, 0.008), 1e-12);
  EXPECT_THROW(runs::replica_spread_from_summary(nlohmann::json{{"T_out_K", 1115.0}}, "plain.json"),
               std::invalid_argument);
}
