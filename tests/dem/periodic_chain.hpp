#pragma once
// A touching chain of n unit spheres round a period of length n (sphere k at z = k + 1/2,
// radius 1/2, all free): each touches the next, the last the first across the period.
#include <vector>

#include "dem/motion.hpp"
#include "dem/periodic_z.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem::testing {

struct PeriodicChain {
  PeriodicZ pz;
  std::vector<Vec3> x;
  std::vector<double> r;
  std::vector<Motion> motion;
};

inline PeriodicChain periodic_chain(int n) {
  PeriodicChain c;
  c.pz.on = true;
  c.pz.lo = 0.0;
  c.pz.hi = n;
  for (int k = 0; k < n; ++k) c.x.push_back({0.0, 0.0, 0.5 + k});
  c.r.assign(c.x.size(), 0.5);
  c.motion.assign(c.x.size(), Motion::free);
  return c;
}

}  // namespace centrec::dem::testing
