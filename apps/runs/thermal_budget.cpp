#include "runs/thermal_budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "runs/thermal_case_run.hpp"
#include "runs/thermal_output.hpp"
#include "thermal/particle_data.hpp"

namespace centrec::runs {

namespace {
const char* const kOutputNames[3] = {"T_out_K", "efficiency", "k_eff_W_mK"};

double output(const BudgetOutputs& o, int i) { return i == 0 ? o.T_out : i == 1 ? o.efficiency : o.k_eff; }

// The same sunlight on the film scaled by f: every form the flux can be given in.
void scale_flux(thermal::FluxProfile& f, double factor) {
  f.q *= factor;
  f.q_base *= factor;
  f.aperture_mean *= factor;
  for (double& q : f.table_q) q *= factor;
}

BudgetInput particle_input(const std::string& name, const std::string& unit, const thermal::RangedValue& v,
                           const std::string& basis, std::function<void(config::ThermalCase&, double)> apply,
                           double nominal) {
  return {name, unit, nominal, v.lo, v.hi, basis, v.source, std::move(apply)};
}
}  // namespace

std::vector<BudgetInput> budget_inputs(const config::ThermalCase& c) {
  const thermal::ParticleData& p = thermal::particle_data(c.particle);
  const thermal::Material& m = c.model.material;
  std::vector<BudgetInput> in;
  // The particle (docs/particle_data.md). A value the case set itself keeps the particle's range.
  in.push_back(particle_input("c_p", "x correlation", p.cp_scale, "published",
                              [](config::ThermalCase& x, double v) { x.model.heat.scale = v; }, c.model.heat.scale));
  in.push_back(particle_input("k_s", "W/(m K)", p.k_s, "assumed",
                              [](config::ThermalCase& x, double v) { x.model.material.k_s = v; }, m.k_s));
  in.push_back(particle_input("absorptance", "", p.alpha, "published",
                              [](config::ThermalCase& x, double v) { x.model.material.alpha = v; }, m.alpha));
  in.push_back(particle_input("emissivity", "", p.epsilon, "partly assumed",
                              [](config::ThermalCase& x, double v) { x.model.material.epsilon = v; }, m.epsilon));
  // The cavity's convection (docs/cavity_model.md, "Convection"): natural convection only.
  const bool correlation = c.model.cavity.enabled && c.model.cavity.convection_correlation;
  in.push_back({"convection h", correlation ? "x correlation" : "x h_conv", 1.0, 0.8, 3.6, "assumed",
                "natural-convection correlation extrapolated to Gr ~ 2e8 (wind and rotation only as the case's own "
                "parts): likely a lower bound; 3.6 x is h ~ 20 W/(m2 K) for the D12 receiver",
                [correlation](config::ThermalCase& x, double v) {
                  if (correlation)
                    x.model.cavity.convection_scale = v;
                  else
                    x.model.surface.h_conv *= v;
                }});
  // The receiver's own losses (docs/cavity_model.md): the wind's part of the convection and
  // the share of the aperture power spilled onto the front plate, from the case's values.
  if (correlation)
    in.push_back({"wind speed", "m/s", c.model.cavity.wind_speed, 0.0, std::max(5.0, c.model.cavity.wind_speed), "assumed",
                  "calm to a moderate breeze at the aperture; forced part from Ma 1993 (no direction dependence) mixed "
                  "with the natural part, n = 3.2",
                  [](config::ThermalCase& x, double v) { x.model.cavity.wind_speed = v; }});
  if (c.model.cavity.enabled)
    in.push_back({"spillage", "of aperture power", c.model.cavity.spillage, 0.0, std::max(0.05, c.model.cavity.spillage),
                  "assumed", "share of the concentrated power landing on the front plate instead of entering; a few "
                  "per cent for a well-aimed field, not measured for CentRec",
                  [](config::ThermalCase& x, double v) { x.model.cavity.spillage = v; }});
  if (c.model.surface.extinction_depth_d != 0.0)
    in.push_back({"Beer-Lambert depth", "x depth", 1.0, 1.0, 2.18, "published",
                  "from the volume-scattering depth of large opaque spheres (Brewster 2004, 0.55 d at phi 0.55) to "
                  "point-scattering theory (1.2 d)",
                  [](config::ThermalCase& x, double v) { x.model.surface.extinction_scale = v; }});
  if (c.model.conductivity.mixing)
    in.push_back({"mixing D", "x film D", 1.0, 0.5, 2.8, "partly assumed",
                  "upper: D/(gamma_dot d^2) = 0.042 of 3D DEM dense flows (Fan et al. 2015; 2D disks measured: 0.027, "
                  "Utter & Behringer 2004) over the DEM's 0.015 in the sheared-bed test (the estimator checked against "
                  "raw trajectories, docs/film_sampling.md); lower assumed",
                  [](config::ThermalCase& x, double v) {
                    for (double& D : x.film.D) D *= v;
                  }});
  // The film top's thermal band (docs/thermal_model.md, "The film top as a participating
  // medium"): the two models are the ends, the case's own choice the nominal; a hypercube
  // sample takes two_flux from 0.5 up. Only where two-flux can run: a 2D film, and in the
  // open-surface model a loss factor of 1 (the film's emission then follows from the column),
  // with the sunlight absorbed by each cell's own phi (thermal::solar_by_local_phi).
  if (!c.grid.lumped && (c.model.cavity.enabled || c.model.surface.loss_factor == 1.0) &&
      thermal::solar_by_local_phi(c.model.surface))
    in.push_back({"film top", "(0 surface, 1 two_flux)", c.model.film_top.two_flux ? 1.0 : 0.0, 0.0, 1.0,
                  "model choice",
                  "thermal.radiation.film_top: the top cell as a grey surface with ZBS radiation below, or the top "
                  "film_top_depth_d as a two-flux participating medium (checked against a Monte Carlo ray trace)",
                  [](config::ThermalCase& x, double v) { x.model.film_top.two_flux = v >= 0.5; }});
  in.push_back({"aperture power", "x", 1.0, 0.95, 1.05, "assumed",
                "typical uncertainty of a measured aperture power or flux map; exact in a simulation",
                [](config::ThermalCase& x, double v) { scale_flux(x.model.flux, v); }});
  return in;
}

BudgetOutputs budget_outputs_at(const config::ThermalCase& c) {
  config::ThermalCase steady = c;
  steady.transient = false;
  const ThermalRun r = run_thermal_case(steady, false);
  return {r.balance.T_out, r.balance.efficiency, section_mean(r.keff, &thermal::KeffSection::k_eff)};
}

BudgetResult run_thermal_budget(const config::ThermalCase& c, const BudgetSettings& s) {
  const auto t0 = std::chrono::steady_clock::now();
  BudgetResult r;
  r.case_path = c.path;
  r.particle = c.particle;
  r.settings = s;
  r.inputs = budget_inputs(c);
  const std::size_t k = r.inputs.size();
  r.nominal = budget_outputs_at(c);
  auto with = [&](const std::vector<double>& values) {
    config::ThermalCase x = c;
    for (std::size_t i = 0; i < k; ++i) r.inputs[i].apply(x, values[i]);
    return budget_outputs_at(x);
  };
  std::vector<double> nominal(k);
  for (std::size_t i = 0; i < k; ++i) nominal[i] = r.inputs[i].nominal;
  // One at a time: each input at both ends of its range, the others nominal.
  r.per_input.resize(k);
  double total[3] = {0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    std::fprintf(stderr, "budget: %s at %.4g and %.4g\n", r.inputs[i].name.c_str(), r.inputs[i].lo, r.inputs[i].hi);
    std::vector<double> v = nominal;
    v[i] = r.inputs[i].lo;
    r.per_input[i].at_lo = with(v);
    v[i] = r.inputs[i].hi;
    r.per_input[i].at_hi = with(v);
    for (int o = 0; o < 3; ++o) {
      r.per_input[i].share_oat[o] =
          thermal::uniform_oat_variance(output(r.per_input[i].at_lo, o), output(r.per_input[i].at_hi, o));
      total[o] += r.per_input[i].share_oat[o];
    }
  }
  for (int o = 0; o < 3; ++o) {
    r.oat_sd[o] = std::sqrt(total[o]);
    for (auto& p : r.per_input) p.share_oat[o] = total[o] > 0 ? p.share_oat[o] / total[o] : 0.0;
  }
  // The Latin hypercube: all inputs drawn together.
  const auto design = thermal::latin_hypercube(s.lhs_samples, static_cast<int>(k), s.seed);
  for (int n = 0; n < s.lhs_samples; ++n) {
    std::vector<double> v(k);
    for (std::size_t i = 0; i < k; ++i) v[i] = r.inputs[i].lo + design[n][i] * (r.inputs[i].hi - r.inputs[i].lo);
    std::fprintf(stderr, "budget: Latin hypercube sample %d of %d\n", n + 1, s.lhs_samples);
    r.lhs_values.push_back(v);
    r.lhs_outputs.push_back(with(v));
  }
  for (int o = 0; o < 3; ++o) {
    std::vector<double> y;
    for (const auto& out : r.lhs_outputs) y.push_back(output(out, o));
    r.lhs_stats[o] = thermal::sample_stats(y);
    if (static_cast<std::size_t>(s.lhs_samples) > k + 1) {
      const thermal::LinearShares ls = thermal::linear_shares(r.lhs_values, y);
      r.lhs_r2[o] = ls.r2;
      double sum = 0.0;
      for (std::size_t i = 0; i < k; ++i) {
        r.per_input[i].src[o] = ls.src[i];
        const double w = r.inputs[i].hi - r.inputs[i].lo;
        r.per_input[i].share_lhs[o] = ls.coefficient[i] * ls.coefficient[i] * w * w / 12.0;
        sum += r.per_input[i].share_lhs[o];
      }
      for (auto& p : r.per_input) p.share_lhs[o] = sum > 0 ? p.share_lhs[o] / sum : 0.0;
    }
  }
  for (int o = 0; o < 3; ++o) r.total_sd[o] = r.oat_sd[o];
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

ReplicaSpread replica_spread_from_summary(const nlohmann::json& summary, const std::string& source) {
  const char* const figures[3] = {"/T_out_K", "/efficiency", "/k_eff/film_mean/k_eff"};
  if (!summary.contains("replicas") || !summary["replicas"].contains("figures"))
    throw std::invalid_argument(source + ": no replicas.figures (a summary.json of `centrec run --replicas N`)");
  ReplicaSpread d;
  d.given = true;
  d.source = source;
  d.count = summary["replicas"].value("count", 0);
  if (d.count < 2) throw std::invalid_argument(source + ": fewer than 2 replicas, no spread to add");
  for (int o = 0; o < 3; ++o) {
    const auto& f = summary["replicas"]["figures"];
    if (!f.contains(figures[o]) || !f[figures[o]].contains("std") || !f[figures[o]]["std"].is_number())
      throw std::invalid_argument(source + ": replicas.figures has no std of " + figures[o]);
    d.sd[o] = f[figures[o]]["std"].get<double>();
  }
  return d;
}

void add_replica_spread(BudgetResult& r, const ReplicaSpread& dem) {
  r.dem = dem;
  for (int o = 0; o < 3; ++o) r.total_sd[o] = std::sqrt(r.oat_sd[o] * r.oat_sd[o] + dem.sd[o] * dem.sd[o]);
}

nlohmann::json budget_json(const BudgetResult& r) {
  auto outputs = [](const BudgetOutputs& o) {
    return nlohmann::json{{"T_out_K", o.T_out}, {"efficiency", o.efficiency}, {"k_eff_W_mK", o.k_eff}};
  };
  nlohmann::json j;
  j["case"] = r.case_path;
  j["particle"] = r.particle;
  j["nominal"] = outputs(r.nominal);
  nlohmann::json inputs = nlohmann::json::array();
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    const BudgetInput& in = r.inputs[i];
    const BudgetInputResult& p = r.per_input[i];
    nlohmann::json e = {{"name", in.name}, {"unit", in.unit},     {"nominal", in.nominal}, {"lo", in.lo},
                        {"hi", in.hi},     {"basis", in.basis},   {"source", in.source},
                        {"at_lo", outputs(p.at_lo)}, {"at_hi", outputs(p.at_hi)}};
    for (int o = 0; o < 3; ++o) {
      e["share_one_at_a_time"][kOutputNames[o]] = p.share_oat[o];
      e["lhs_src"][kOutputNames[o]] = p.src[o];
      e["share_latin_hypercube"][kOutputNames[o]] = p.share_lhs[o];
    }
    inputs.push_back(e);
  }
  j["inputs"] = inputs;
  nlohmann::json lhs = {{"samples", r.settings.lhs_samples}, {"seed", r.settings.seed}};
  for (int o = 0; o < 3; ++o) {
    const thermal::SampleStats& st = r.lhs_stats[o];
    j["one_at_a_time_sd"][kOutputNames[o]] = r.oat_sd[o];
    lhs[kOutputNames[o]] = {{"mean", st.mean}, {"sd", st.sd}, {"min", st.min}, {"max", st.max},
                            {"p05", st.p05},   {"p95", st.p95}, {"linear_fit_r2", r.lhs_r2[o]}};
  }
  lhs["values"] = r.lhs_values;
  nlohmann::json outs = nlohmann::json::array();
  for (const auto& o : r.lhs_outputs) outs.push_back(outputs(o));
  lhs["outputs"] = outs;
  j["latin_hypercube"] = lhs;
  if (r.dem.given) {
    j["dem_replicas"] = {{"source", r.dem.source}, {"count", r.dem.count}};
    for (int o = 0; o < 3; ++o) j["dem_replicas"]["sd"][kOutputNames[o]] = r.dem.sd[o];
  }
  for (int o = 0; o < 3; ++o) j["total_sd"][kOutputNames[o]] = r.total_sd[o];
  j["wall_time_s"] = r.seconds;
  return j;
}

void print_budget_table(const BudgetResult& r) {
  std::printf("centrec budget %s (particle %s): T_out %.2f K, efficiency %.4f, k_eff %.4g W/(m K)\n",
              r.case_path.c_str(), r.particle.c_str(), r.nominal.T_out, r.nominal.efficiency, r.nominal.k_eff);
  std::printf("\n| input | range | basis | T_out at lo / hi, K | efficiency at lo / hi | k_eff at lo / hi, W/(m K) | "
              "share of var T_out: one at a time / hypercube | share of var efficiency | share of var k_eff "
              "|\n|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    const BudgetInput& in = r.inputs[i];
    const BudgetInputResult& p = r.per_input[i];
    const std::string unit = in.unit.empty() ? "" : " " + in.unit;
    std::printf("| %s | %.4g-%.4g%s | %s | %+.2f / %+.2f | %+.4f / %+.4f | %+.4f / %+.4f | %.1f %% / %.1f %% | "
                "%.1f %% / %.1f %% | %.1f %% / %.1f %% |\n",
                in.name.c_str(), in.lo, in.hi, unit.c_str(), in.basis.c_str(), p.at_lo.T_out - r.nominal.T_out,
                p.at_hi.T_out - r.nominal.T_out, p.at_lo.efficiency - r.nominal.efficiency,
                p.at_hi.efficiency - r.nominal.efficiency, p.at_lo.k_eff - r.nominal.k_eff,
                p.at_hi.k_eff - r.nominal.k_eff, 100.0 * p.share_oat[0], 100.0 * p.share_lhs[0],
                100.0 * p.share_oat[1], 100.0 * p.share_lhs[1], 100.0 * p.share_oat[2], 100.0 * p.share_lhs[2]);
  }
  std::printf("\none at a time (uniform inputs, linear): sd T_out %.2f K, efficiency %.4f, k_eff %.4f W/(m K)\n",
              r.oat_sd[0], r.oat_sd[1], r.oat_sd[2]);
  if (r.dem.given)
    std::printf("DEM seeds (%d replicas, %s): sd T_out %.2f K, efficiency %.4f, k_eff %.4f W/(m K); with the inputs: "
                "sd T_out %.2f K, efficiency %.4f, k_eff %.4f W/(m K)\n",
                r.dem.count, r.dem.source.c_str(), r.dem.sd[0], r.dem.sd[1], r.dem.sd[2], r.total_sd[0], r.total_sd[1],
                r.total_sd[2]);
  const thermal::SampleStats* st = r.lhs_stats;
  std::printf("Latin hypercube, %d samples, seed %llu: T_out %.2f +- %.2f K (5-95 %% %.2f-%.2f), efficiency %.4f +- "
              "%.4f (%.4f-%.4f), k_eff %.4f +- %.4f W/(m K) (%.4f-%.4f); linear fit R^2 %.3f / %.3f / %.3f\n",
              r.settings.lhs_samples, static_cast<unsigned long long>(r.settings.seed), st[0].mean, st[0].sd,
              st[0].p05, st[0].p95, st[1].mean, st[1].sd, st[1].p05, st[1].p95, st[2].mean, st[2].sd, st[2].p05,
              st[2].p95, r.lhs_r2[0], r.lhs_r2[1], r.lhs_r2[2]);
  std::printf("%zu + %d steady solves in %.1f s\n", 2 * r.inputs.size() + 1, r.settings.lhs_samples, r.seconds);
}

}  // namespace centrec::runs
