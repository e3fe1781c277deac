#include "profile_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace centrec::film {

LineFit fit_line(const double* x, const double* y, std::size_t n, double lo, double hi) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (x[i] < lo || x[i] > hi || !std::isfinite(y[i])) continue;
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
    ++m;
  }
  const double det = m * sxx - sx * sx;
  if (m < 2 || det == 0.0) throw std::invalid_argument("fit_line: fewer than two distinct points in the window");
  LineFit f;
  f.points = m;
  f.slope = (m * sxy - sx * sy) / det;
  f.intercept = (sy - f.slope * sx) / m;
  return f;
}

LineFit fit_profile(const std::vector<ProfileBin>& profile, double bin_width, double lo, double hi) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < profile.size(); ++k) {
    x.push_back((k + 0.5) * bin_width);
    y.push_back(profile[k].mean);
  }
  return fit_line(x.data(), y.data(), x.size(), lo, hi);
}

}  // namespace centrec::film
