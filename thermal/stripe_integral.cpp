#include "stripe_integral.hpp"

#include <algorithm>

namespace centrec::thermal {

namespace {
template <class F>
double piecewise_simpson(const FilmField& f, double a, double b, F g) {
  if (!(b > a)) return 0.0;
  double sum = 0.0, lo = a;
  // Break at every eta point inside (a, b): the integrand is smooth between them.
  auto it = std::upper_bound(f.eta.begin(), f.eta.end(), a);
  while (lo < b) {
    const double hi = (it != f.eta.end() && *it < b) ? *it++ : b;
    sum += (hi - lo) / 6.0 * (g(lo) + 4.0 * g(0.5 * (lo + hi)) + g(hi));
    lo = hi;
  }
  return sum;
}
}  // namespace

double stripe_integral_phi_u(const FilmField& f, double z, double a, double b) {
  return piecewise_simpson(f, a, b, [&](double e) { return f.sample(f.phi, z, e) * f.sample(f.u, z, e); });
}

double stripe_integral_phi(const FilmField& f, double z, double a, double b) {
  return piecewise_simpson(f, a, b, [&](double e) { return f.sample(f.phi, z, e); });
}

}  // namespace centrec::thermal
