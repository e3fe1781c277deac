#pragma once
// The `sweep:` section of a coupled case: the operating window of
// `centrec sweep`, rotational speed x mass flow of the receiver (or of the DEM drum when the
// case has no receiver), and how many coupled runs go in parallel.
#include <vector>

#include "config/strict_yaml.hpp"

namespace centrec::config {

struct SweepSpec {
  std::vector<double> speed_rpm;  // rev/min
  std::vector<double> mass_flow;  // kg/s
  int parallel = 2;               // concurrent processes
};

SweepSpec read_sweep(MapReader r);

}  // namespace centrec::config
