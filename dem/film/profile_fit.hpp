#pragma once
// Least-squares straight line through a binned profile over a wall-distance window:
// the paper fits its Fig 6(a) velocity profile "between 1 d_p and 4 d_p".
#include <cstddef>
#include <vector>

#include "dem/film/period_profile.hpp"

namespace centrec::film {

struct LineFit {
  double slope = 0.0;       // per unit of x
  double intercept = 0.0;
  std::size_t points = 0;   // bins used
};

// Fits y = intercept + slope x over the points with lo <= x <= hi and finite y.
// Throws std::invalid_argument if fewer than two points qualify.
LineFit fit_line(const double* x, const double* y, std::size_t n, double lo, double hi);

// The same over a profile whose bin k sits at x = (k + 0.5) * bin_width.
LineFit fit_profile(const std::vector<ProfileBin>& profile, double bin_width, double lo, double hi);

}  // namespace centrec::film
