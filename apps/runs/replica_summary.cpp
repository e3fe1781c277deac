#include "runs/replica_summary.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "runs/headline_figures.hpp"

namespace centrec::runs {

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
  for (const HeadlineFigure& fig : headline_figures()) {
    std::vector<double> v;
    for (std::size_t k = 0; k < summaries.size(); ++k) {
      double x = 0.0;
      if (!headline_value(summaries[k], fig, x))
        throw std::invalid_argument("replica " + dirs[k] + ": summary.json has no number at " + fig.pointer);
      v.push_back(x);
    }
    const Spread s = spread(v);
    out[nlohmann::json::json_pointer(fig.pointer)] = s.mean;
    figures[fig.pointer] = {{"mean", s.mean}, {"std", s.std}, {"values", v}};
  }
  block["figures"] = figures;
  block["note"] =
      "the figures listed here are, at the top level of this file, their means over the replicas; every other "
      "entry is replica 0's (seed " +
      std::to_string(seeds.front()) + "); std is the sample standard deviation (N - 1)";
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
