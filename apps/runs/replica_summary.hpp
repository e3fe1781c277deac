#pragma once
// The spread of a coupled run over DEM seeds (`centrec run --replicas N`): the same case run
// with N seeds, each a complete run of its own; this combines their summary.json into one.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace centrec::runs {

// Mean and sample standard deviation (N - 1; 0 for one value) of values.
struct Spread {
  double mean = 0.0, std = 0.0;
};
Spread spread(const std::vector<double>& values);

// The combined summary: replica 0's summary.json with every figure of headline_figures()
// (runs/headline_figures.hpp)
// replaced by its mean over the replicas, dem.steady true only if every replica was steady,
// the warnings of all replicas, and a "replicas" block: count, seeds, dirs and, per
// figure, mean, std and the values in seed order. Throws std::invalid_argument if a
// summary lacks a figure or the list is empty.
nlohmann::json combine_replicas(const std::vector<nlohmann::json>& summaries, const std::vector<std::uint64_t>& seeds,
                                const std::vector<std::string>& dirs);

}  // namespace centrec::runs
