#include "coupling/particle_path_heating.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace centrec::coupling {

namespace {
// Fractional cell index of x on centres spaced h from h/2, clamped to [0, n - 1].
void locate(double x, double h, int n, int& i0, double& w) {
  const double s = std::clamp(x / h - 0.5, 0.0, static_cast<double>(n - 1));
  i0 = std::min(static_cast<int>(s), n - 2 < 0 ? 0 : n - 2);
  w = n > 1 ? s - i0 : 0.0;
}
}  // namespace

bool FilmTemperatureField::at(double zq, double eta, double& T_out, double& k_out) const {
  const int nz = static_cast<int>(z.size());
  int i0 = 0;
  double wz = 0.0;
  locate(zq, length / nz, nz, i0, wz);
  const int i1 = std::min(i0 + 1, nz - 1);
  const double t = (1.0 - wz) * thickness[static_cast<std::size_t>(i0)] + wz * thickness[static_cast<std::size_t>(i1)];
  if (eta > t) return false;
  int j0 = 0;
  double wx = 0.0;
  locate(std::max(eta, 0.0) / t, 1.0 / nxi, nxi, j0, wx);
  const int j1 = std::min(j0 + 1, nxi - 1);
  auto bilinear = [&](const std::vector<double>& v) {
    auto a = [&](int i, int j) { return v[static_cast<std::size_t>(i * nxi + j)]; };
    return (1.0 - wz) * ((1.0 - wx) * a(i0, j0) + wx * a(i0, j1)) + wz * ((1.0 - wx) * a(i1, j0) + wx * a(i1, j1));
  };
  T_out = bilinear(T);
  k_out = bilinear(k_conduction);
  return true;
}

std::vector<HeatedPath> heat_paths(const std::vector<film::ParticlePath>& paths, const std::vector<double>& weights,
                                   const std::vector<film::TrackSnapshot>& tracks, const FilmTemperatureField& field,
                                   const PathHeatingSpec& spec) {
  if (weights.size() != paths.size()) throw std::invalid_argument("heat_paths: one weight per path");
  if (field.z.empty() || field.nxi < 1 || field.T.size() != field.z.size() * static_cast<std::size_t>(field.nxi))
    throw std::invalid_argument("heat_paths: an empty or inconsistent temperature field");
  const double d2 = spec.material.d * spec.material.d;
  std::vector<HeatedPath> out;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (!(weights[p] > 0.0)) continue;
    const film::ParticlePath& path = paths[p];
    HeatedPath h;
    h.residence = path.residence() * spec.scale;
    h.weight = weights[p];
    double Tp = spec.T_in;
    h.T_peak = Tp;
    // The film's temperature and the relaxation time at point k (false: in flight).
    auto film_at = [&](std::size_t k, double& Tf, double& tau) {
      double k_c = 0.0;
      if (!field.at(path.z[k] * spec.scale, spec.drum_radius - path.r[k], Tf, k_c)) return false;
      tau = spec.relax ? spec.material.rho_s * spec.heat.cp(Tp) * d2 / (12.0 * k_c) : 0.0;
      return true;
    };
    double T0 = 0.0, tau0 = 0.0;
    bool on0 = film_at(0, T0, tau0);
    for (std::size_t k = 1; k < path.z.size(); ++k) {
      double T1 = 0.0, tau1 = 0.0;
      const bool on1 = film_at(k, T1, tau1);
      const double dt = (tracks[path.first + k].time - tracks[path.first + k - 1].time) * spec.scale;
      if (on0 && on1) {
        // y' = (a + b t - y) / tau over [0, dt] with a + b t from T0 to T1, tau the mean.
        const double tau = 0.5 * (tau0 + tau1);
        if (tau <= 0.0) {
          Tp = T1;
        } else {
          const double e = std::exp(-dt / tau), b = (T1 - T0) / dt;
          Tp = T1 - b * tau * (1.0 - e) + (Tp - T0) * e;
        }
      } else if (on1 && !spec.relax) {
        Tp = T1;  // landed on the film: tau = 0 reads it at once
      }
      h.T_peak = std::max(h.T_peak, Tp);
      T0 = T1;
      tau0 = tau1;
      on0 = on1;
    }
    h.T_out = Tp;
    out.push_back(h);
  }
  return out;
}

}  // namespace centrec::coupling
