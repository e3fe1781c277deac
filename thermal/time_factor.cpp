#include "time_factor.hpp"

#include <algorithm>

namespace centrec::thermal {

namespace {
// 0 before t0, 1 after t0 + ramp, linear in between.
double edge(double t, double t0, double ramp) {
  if (t <= t0) return 0.0;
  if (ramp <= 0.0 || t >= t0 + ramp) return 1.0;
  return (t - t0) / ramp;
}
}  // namespace

double TimeFactor::at(double t) const {
  switch (kind) {
    case Kind::constant:
      return 1.0;
    case Kind::step:
      return 1.0 + (level - 1.0) * edge(t, t_start, ramp);
    case Kind::pulse:
      return 1.0 + (level - 1.0) * (edge(t, t_start, ramp) - edge(t, t_end, ramp));
  }
  return 1.0;
}

int TimeFactor::breakpoints(double out[4]) const {
  int n = 0;
  if (kind == Kind::constant) return 0;
  out[n++] = t_start;
  out[n++] = t_start + ramp;
  if (kind == Kind::pulse) {
    out[n++] = t_end;
    out[n++] = t_end + ramp;
  }
  std::sort(out, out + n);
  return n;
}

}  // namespace centrec::thermal
