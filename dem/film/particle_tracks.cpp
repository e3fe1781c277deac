#include "dem/film/particle_tracks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace centrec::film {

TrackSnapshot track_snapshot(const ParticleColumns& s) {
  TrackSnapshot t;
  t.time = s.time;
  t.id = s.id;
  t.z = s.z;
  t.r.resize(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) t.r[i] = std::hypot(s.x[i], s.y[i]);
  return t;
}

std::vector<ParticlePath> complete_paths(const std::vector<TrackSnapshot>& tracks) {
  const std::size_t K = tracks.size();
  for (std::size_t k = 1; k < K; ++k)
    if (!(tracks[k].time > tracks[k - 1].time))
      throw std::invalid_argument("particle tracks: snapshot " + std::to_string(k) +
                                  " is not later than the one before");
  // Where each particle was first and last seen, and how often (a gap = a reappearance).
  struct Seen {
    std::size_t first, last, count;
  };
  std::unordered_map<std::int64_t, Seen> seen;
  for (std::size_t k = 0; k < K; ++k)
    for (const std::int64_t id : tracks[k].id) {
      auto [it, fresh] = seen.try_emplace(id, Seen{k, k, 0});
      it->second.last = k;
      ++it->second.count;
      (void)fresh;
    }
  std::vector<ParticlePath> paths;
  for (const auto& [id, s] : seen) {
    if (s.count != s.last - s.first + 1)
      throw std::invalid_argument("particle tracks: particle " + std::to_string(id) +
                                  " is missing from a snapshot between its first and last");
    if (s.first == 0 || s.last + 1 >= K) continue;
    ParticlePath p;
    p.id = id;
    p.first = s.first;
    p.entry = 0.5 * (tracks[s.first - 1].time + tracks[s.first].time);
    p.exit = 0.5 * (tracks[s.last].time + tracks[s.last + 1].time);
    paths.push_back(std::move(p));
  }
  std::sort(paths.begin(), paths.end(), [](const ParticlePath& a, const ParticlePath& b) { return a.id < b.id; });
  // The points, snapshot by snapshot (a particle's position in a snapshot found by its id).
  std::unordered_map<std::int64_t, std::size_t> path_of;
  for (std::size_t i = 0; i < paths.size(); ++i) path_of.emplace(paths[i].id, i);
  for (std::size_t k = 0; k < K; ++k)
    for (std::size_t j = 0; j < tracks[k].id.size(); ++j)
      if (const auto it = path_of.find(tracks[k].id[j]); it != path_of.end()) {
        paths[it->second].z.push_back(tracks[k].z[j]);
        paths[it->second].r.push_back(tracks[k].r[j]);
      }
  return paths;
}

ResidenceTimes residence_times(const std::vector<TrackSnapshot>& tracks, const std::vector<ParticlePath>& paths) {
  ResidenceTimes rt;
  if (tracks.size() < 3) return rt;
  rt.window = tracks.back().time - tracks.front().time;
  rt.resolution = rt.window / static_cast<double>(tracks.size() - 1);
  std::unordered_map<std::int64_t, int> in_first, in_last;
  for (const std::int64_t id : tracks.front().id) in_first[id] = 1;
  for (const std::int64_t id : tracks.back().id) in_last[id] = 1;
  std::unordered_map<std::int64_t, int> all;
  for (const TrackSnapshot& s : tracks)
    for (const std::int64_t id : s.id) all[id] = 1;
  for (const auto& [id, one] : all) {
    rt.fed += in_first.count(id) == 0;
    rt.left += in_last.count(id) == 0;
  }
  for (const ParticlePath& p : paths) {
    const double tau = p.residence();
    rt.tau.push_back(tau);  // a residence seen for too few feeds to weigh gets weight 0
    rt.weight.push_back(tau < rt.window - rt.resolution ? rt.window / (rt.window - tau) : 0.0);
  }
  return rt;
}

double ResidenceTimes::mean() const {
  double s = 0.0, w = 0.0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    s += weight[i] * tau[i];
    w += weight[i];
  }
  return w > 0.0 ? s / w : std::nan("");
}

double weighted_quantile(const std::vector<double>& values, const std::vector<double>& weights, double p) {
  if (values.empty()) return std::nan("");
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double acc = 0.0;
  for (const std::size_t i : order) {
    acc += weights[i];
    if (acc >= p * total) return values[i];
  }
  return values[order.back()];
}

double ResidenceTimes::quantile(double p) const { return weighted_quantile(tau, weight, p); }

double ResidenceTimes::coverage() const {
  return fed > 0 ? std::accumulate(weight.begin(), weight.end(), 0.0) / static_cast<double>(fed) : std::nan("");
}

double ResidenceTimes::share_below(double t) const {
  double below = 0.0, total = 0.0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    total += weight[i];
    if (tau[i] < t) below += weight[i];
  }
  return total > 0.0 ? below / total : std::nan("");
}

}  // namespace centrec::film
