#include "film_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace centrec::thermal {

namespace {
// Index i and weight w with x ~ (1-w) xs[i] + w xs[i+1], clamped to the ends.
void bracket(const std::vector<double>& xs, double x, std::size_t& i, double& w) {
  if (xs.size() == 1 || x <= xs.front()) {
    i = 0;
    w = 0.0;
    return;
  }
  if (x >= xs.back()) {
    i = xs.size() - 2;
    w = 1.0;
    return;
  }
  i = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
  w = (x - xs[i]) / (xs[i + 1] - xs[i]);
}

void require_increasing(const std::vector<double>& xs, const char* name) {
  for (std::size_t i = 1; i < xs.size(); ++i)
    if (!(xs[i] > xs[i - 1]))
      throw std::invalid_argument(std::string("film field: ") + name + " must increase strictly (index " +
                                  std::to_string(i) + ")");
}
}  // namespace

double FilmField::thickness(double zq) const {
  std::size_t i;
  double w;
  bracket(z, zq, i, w);
  if (z.size() == 1) return t[0];
  return (1.0 - w) * t[i] + w * t[i + 1];
}

double FilmField::sample(const std::vector<double>& field, double zq, double etaq) const {
  std::size_t i, j;
  double wz, we;
  bracket(z, zq, i, wz);
  bracket(eta, etaq, j, we);
  const std::size_t n = neta();
  auto at = [&](std::size_t a, std::size_t b) { return field[a * n + b]; };
  const std::size_t i1 = z.size() == 1 ? i : i + 1;
  const std::size_t j1 = eta.size() == 1 ? j : j + 1;
  const double lo = (1.0 - we) * at(i, j) + we * at(i, j1);
  const double hi = (1.0 - we) * at(i1, j) + we * at(i1, j1);
  return (1.0 - wz) * lo + wz * hi;
}

void FilmField::check() const {
  if (z.empty()) throw std::invalid_argument("film field: no axial sections");
  if (eta.size() < 2) throw std::invalid_argument("film field: need at least two wall-distance points");
  require_increasing(z, "z");
  require_increasing(eta, "eta");
  if (eta.front() != 0.0) throw std::invalid_argument("film field: eta[0] must be 0 (the wall)");
  const std::size_t n = nz() * neta();
  if (t.size() != nz()) throw std::invalid_argument("film field: t needs one value per section");
  if (u.size() != n || phi.size() != n || D.size() != n)
    throw std::invalid_argument("film field: u, phi and D need nz * neta values each");
  for (std::size_t i = 0; i < nz(); ++i) {
    if (!(t[i] > 0.0))
      throw std::invalid_argument("film field: thickness must be > 0 (section " + std::to_string(i) + ", t = " +
                                  std::to_string(t[i]) + " m)");
    if (t[i] > eta.back() * (1.0 + 1e-12))
      throw std::invalid_argument("film field: thickness exceeds the last eta point (section " +
                                  std::to_string(i) + ")");
  }
  // Bounds of a physical film (the ranges of film.analytic): a field beyond them is a
  // damaged or mistaken file, not a film.
  for (std::size_t i = 0; i < nz(); ++i)
    if (!std::isfinite(z[i]) || !(t[i] <= 0.5))
      throw std::invalid_argument("film field: section " + std::to_string(i) + " has z = " + std::to_string(z[i]) +
                                  " m, t = " + std::to_string(t[i]) + " m (z must be finite, t at most 0.5 m)");
  for (std::size_t k = 0; k < n; ++k) {
    if (!(u[k] <= 100.0))
      throw std::invalid_argument("film field: axial velocity " + std::to_string(u[k]) +
                                  " m/s is not that of a particle film (at most 100 m/s)");
    if (!(D[k] <= 1.0))
      throw std::invalid_argument("film field: dispersion " + std::to_string(D[k]) + " m2/s is beyond 1 m2/s");
    // Inside the film there is solid everywhere; above its top a point may lie in an empty bin
    // (a film whose profile falls to nothing within a bin of its top, coupling/film_mapping.cpp).
    const bool in_film = eta[k % neta()] <= t[k / neta()];
    if (!((in_film ? phi[k] > 0.0 : phi[k] >= 0.0) && phi[k] < 1.0))
      throw std::invalid_argument("film field: solid fraction must be in " + std::string(in_film ? "(0, 1)" : "[0, 1)") +
                                  (in_film ? " inside the film" : " above the film's top") + ", got " +
                                  std::to_string(phi[k]));
    if (!(u[k] >= 0.0))
      throw std::invalid_argument("film field: axial velocity must be >= 0 (the film flows toward the outlet), got " +
                                  std::to_string(u[k]));
    if (!(D[k] >= 0.0)) throw std::invalid_argument("film field: dispersion must be >= 0");
  }
}

}  // namespace centrec::thermal
