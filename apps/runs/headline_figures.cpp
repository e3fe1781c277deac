#include "runs/headline_figures.hpp"

namespace centrec::runs {

const std::vector<HeadlineFigure>& headline_figures() {
  static const std::vector<HeadlineFigure> f = {
      {"/T_out_K", "T_out_K", "K"},
      {"/efficiency", "efficiency", "-"},
      {"/k_eff/film_mean/k_eff", "k_eff_W_mK", "W/(m K)"},
      {"/k_eff/film_mean/bed_conduction", "k_bed_W_mK", "W/(m K)"},
      {"/k_eff/film_mean/radiation", "k_rad_W_mK", "W/(m K)"},
      {"/k_eff/film_mean/mixing", "k_mix_W_mK", "W/(m K)"},
      {"/film/mean_thickness_d", "film_thickness_d", "d"},
      {"/mass_flow_kg_s", "imposed_mdot_kg_s", "kg/s"},
      {"/coupling/flow_closure_mean", "flow_closure", "-"},
      {"/coupling/imposed_velocity_factor", "velocity_factor", "-"},
      {"/dem/measured_mdot_kg_s", "dem_mdot_kg_s", "kg/s"},
  };
  return f;
}

const std::vector<HeadlineFigure>& point_inputs() {
  static const std::vector<HeadlineFigure> f = {
      {"/point/speed_rpm", "speed_rpm", "rpm"},
      {"/point/mass_flow_kg_s", "mass_flow_kg_s", "kg/s"},
      {"/point/T_in_K", "T_in_K", "K"},
      {"/point/flux_film_mean_W_m2", "flux_film_mean_W_m2", "W/m2"},
      {"/point/seed", "seed", "-"},
      {"/point/dt_s", "dt_s", "s"},
  };
  return f;
}

bool headline_value(const nlohmann::json& summary, const HeadlineFigure& f, double& out) {
  const nlohmann::json::json_pointer ptr(f.pointer);
  if (!summary.contains(ptr) || !summary.at(ptr).is_number()) return false;
  out = summary.at(ptr).get<double>();
  return true;
}

}  // namespace centrec::runs
