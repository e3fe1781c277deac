#pragma once
// The error budget of a thermal case (docs/error_budget.md): the stated ranges of the
// uncertain inputs (the particle's c_p, k_s, absorptance and emissivity from
// thermal/particle_data.hpp; the cavity's convection, the Beer-Lambert depth, the film's
// mixing, the film-top radiation model and the aperture power) propagated to the outlet temperature, the receiver
// efficiency and k_eff, one at a time and by a seeded Latin hypercube. Each sample is a
// steady thermal solve of the case with the inputs changed; nothing else is changed.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config/case_thermal.hpp"
#include "thermal/error_budget.hpp"

namespace centrec::runs {

// One uncertain input: its range (uniform), how well that range is backed, and how a value
// enters the case.
struct BudgetInput {
  std::string name, unit;
  double nominal = 0.0, lo = 0.0, hi = 0.0;
  std::string basis;   // "published", "partly assumed", "assumed" or "model choice"
  std::string source;  // where the value and the range come from
  std::function<void(config::ThermalCase&, double)> apply;
};

// The inputs that act on this case: a mixing range only with mixing on, a Beer-Lambert range
// only with extinction absorption, the film-top model only where two-flux can run.
std::vector<BudgetInput> budget_inputs(const config::ThermalCase& c);

struct BudgetOutputs {
  double T_out = 0.0, efficiency = 0.0, k_eff = 0.0;  // K, -, W/(m K)
};
BudgetOutputs budget_outputs_at(const config::ThermalCase& c);  // one steady solve

struct BudgetSettings {
  int lhs_samples = 40;
  std::uint64_t seed = 12345;
};

struct BudgetInputResult {
  BudgetOutputs at_lo, at_hi;  // one at a time, the others nominal
  double share_oat[3] = {0, 0, 0};  // of the one-at-a-time variance: T_out, efficiency, k_eff
  double src[3] = {0, 0, 0};        // standardised regression coefficients on the hypercube
  // Of the hypercube's linear fit: b_i^2 (hi - lo)^2 / 12 over its sum, the fit's variance for
  // independent uniform inputs (free of the chance correlations between a few samples' inputs).
  double share_lhs[3] = {0, 0, 0};
};

// The DEM's own spread over seeds (`centrec run --replicas N`: its summary.json's
// replicas.figures std of T_out, efficiency and k_eff), independent of the thermal inputs, so
// it adds to the one-at-a-time variance in quadrature.
struct ReplicaSpread {
  bool given = false;
  std::string source;
  int count = 0;
  double sd[3] = {0, 0, 0};  // T_out, efficiency, k_eff
};

struct BudgetResult {
  std::string case_path, particle;
  BudgetOutputs nominal;
  std::vector<BudgetInput> inputs;
  std::vector<BudgetInputResult> per_input;
  double oat_sd[3] = {0, 0, 0};  // sqrt of the summed one-at-a-time variances
  BudgetSettings settings;
  std::vector<std::vector<double>> lhs_values;  // [sample][input], in the inputs' units
  std::vector<BudgetOutputs> lhs_outputs;
  thermal::SampleStats lhs_stats[3];
  double lhs_r2[3] = {0, 0, 0};
  double seconds = 0.0;
  ReplicaSpread dem;
  double total_sd[3] = {0, 0, 0};  // one-at-a-time inputs and, if given, the DEM seeds
};

// Reads it from that summary; throws std::invalid_argument naming what the summary lacks.
ReplicaSpread replica_spread_from_summary(const nlohmann::json& summary, const std::string& source);

BudgetResult run_thermal_budget(const config::ThermalCase& c, const BudgetSettings& s);
// With the DEM's spread: each output's sd over inputs and seeds, sqrt(oat_sd^2 + sd_dem^2).
void add_replica_spread(BudgetResult& r, const ReplicaSpread& dem);
nlohmann::json budget_json(const BudgetResult& r);
void print_budget_table(const BudgetResult& r);

}  // namespace centrec::runs
