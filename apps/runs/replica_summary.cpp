#include "runs/replica_summary.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

namespace centrec::runs {

const std::vector<std::string>& replica_figures() {
  static const std::vector<std::string> f = {
      "/T_out_K",          "/efficiency",          "/k_eff/film_mean/k_eff",
      "/k_eff/film_mean/bed_conduction", "/k_eff/film_mean/radiation", "/k_eff/film_mean/mixing",
      "/film/mean_thickness_d",          "/coupling/flow_closure_mean", "/coupling/imposed_velocity_factor",
      "/dem/measured_mdot_kg_s"};
  return f;
}

Spread spread(const std::vector<double>& values) {
  Spread s;
  if (values.empty()) return s;
  for (double v : values) s.mean += v;
  s.mean /= static_cast<double>(values.size());
  if (values.size() < 2) return s;
  double ss = 0.0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(ss / static_cast<double>(values.size() - 1));
  return s;
}

nlohmann::json combine_replicas(const std::vector<nlohmann::json>& summaries, const std::vector<std::uint64_t>& seeds,
                                const std::vector<std::string>& dirs) {
  if (summaries.empty() || summaries.size() != seeds.size() || summaries.size() != dirs.size())
    throw std::invalid_argument("combine_replicas: one summary, seed and folder per replica");
  nlohmann::json out = summaries.front();
  nlohmann::json block = {{"count", summaries.size()}, {"seeds", seeds}, {"dirs", dirs}};
  nlohmann::json figures = nlohmann::json::object();
  for (const std::string& path : replica_figures()) {
    const nlohmann::json::json_pointer ptr(path);
    std::vector<double> v;
    for (std::size_t k = 0; k < summaries.size(); ++k) {
      if (!summaries[k].contains(ptr) || !summaries[k].at(ptr).is_number())
        throw std::invalid_argument("replica " + dirs[k] + ": summary.json has no number at " + path);
      v.push_back(summaries[k].at(ptr).get<double>());
    }
    const Spread s = spread(v);
    out[ptr] = s.mean;
    figures[path] = {{"mean", s.mean}, {"std", s.std}, {"values", v}};
  }
  block["figures"] = figures;
  block["note"] =
      "the figures listed here are, at the top level of this file, their means over the replicas; every other "
      "entry is replica 0's (seed " + std::to_string(seeds.front()) + "); std is the sample standard deviation (N - 1)";
  bool steady = true;
  std::set<std::string> warnings;
  for (const auto& s : summaries) {
    if (s.contains("dem")) steady = steady && s["dem"].value("steady", false);
    if (s.contains("warnings"))
      for (const auto& w : s["warnings"]) warnings.insert(w.get<std::string>());
  }
  if (out.contains("dem")) out["dem"]["steady"] = steady;
  out["warnings"] = std::vector<std::string>(warnings.begin(), warnings.end());
  out["replicas"] = block;
  return out;
}

}  // namespace centrec::runs
