#include "film_surrogate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace centrec::coupling {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kQuadricMinimumPoints = 8;  // 6 coefficients, and a leave-one-out fit of 7

int basis_size(SurrogateBasis b) { return b == SurrogateBasis::plane ? 3 : 6; }

// The basis at (speed, mass flow), in the map's standardised logarithms (centred on the
// map's mean, scaled by its spread: the fit's conditioning does not depend on the units).
std::vector<double> features(SurrogateBasis b, const Standardise& st, double speed_rpm, double mass_flow) {
  const double x = (std::log(speed_rpm) - st.x0) / st.sx, y = (std::log(mass_flow) - st.y0) / st.sy;
  if (b == SurrogateBasis::plane) return {1.0, x, y};
  return {1.0, x, y, x * x, x * y, y * y};
}

// Least-squares coefficients of `values` (one row per point) over the points `use`, by
// modified Gram-Schmidt QR (twice orthogonalised; at most 6 columns); empty when the points
// do not determine the basis (too few, or on one line: a column left with < 1e-8 of its norm).
std::vector<std::vector<double>> least_squares(SurrogateBasis b, const Standardise& st,
                                               const std::vector<SurrogateSample>& s,
                                               const std::vector<std::vector<double>>& values,
                                               const std::vector<std::size_t>& use) {
  const std::size_t p = basis_size(b), m = use.size();
  if (m < p) return {};
  std::vector<std::vector<double>> q(p, std::vector<double>(m));  // columns of A, then of Q
  for (std::size_t r = 0; r < m; ++r) {
    const auto f = features(b, st, s[use[r]].speed_rpm, s[use[r]].mass_flow);
    for (std::size_t c = 0; c < p; ++c) q[c][r] = f[c];
  }
  auto dot = [m](const std::vector<double>& a, const std::vector<double>& c) {
    double sum = 0.0;
    for (std::size_t r = 0; r < m; ++r) sum += a[r] * c[r];
    return sum;
  };
  std::vector<std::vector<double>> R(p, std::vector<double>(p, 0.0));
  for (std::size_t c = 0; c < p; ++c) {
    const double norm0 = std::sqrt(dot(q[c], q[c]));
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t k = 0; k < c; ++k) {
        const double proj = dot(q[k], q[c]);
        R[k][c] += proj;
        for (std::size_t r = 0; r < m; ++r) q[c][r] -= proj * q[k][r];
      }
    const double norm = std::sqrt(dot(q[c], q[c]));
    if (!(norm > 1e-8 * norm0)) return {};
    R[c][c] = norm;
    for (double& v : q[c]) v /= norm;
  }
  const std::size_t k = values[use[0]].size();
  std::vector<std::vector<double>> coef(k, std::vector<double>(p));
  std::vector<double> rhs(m);
  for (std::size_t j = 0; j < k; ++j) {
    for (std::size_t r = 0; r < m; ++r) rhs[r] = values[use[r]][j];
    for (std::size_t c = p; c-- > 0;) {  // R coef = Q^T rhs, back substitution
      double v = dot(q[c], rhs);
      for (std::size_t c2 = c + 1; c2 < p; ++c2) v -= R[c][c2] * coef[j][c2];
      coef[j][c] = v / R[c][c];
    }
  }
  return coef;
}

std::vector<double> evaluate(SurrogateBasis b, const Standardise& st, const std::vector<std::vector<double>>& coef,
                             double speed_rpm, double mass_flow) {
  const auto f = features(b, st, speed_rpm, mass_flow);
  std::vector<double> out(coef.size(), 0.0);
  for (std::size_t j = 0; j < coef.size(); ++j)
    for (std::size_t q = 0; q < f.size(); ++q) out[j] += coef[j][q] * f[q];
  return out;
}

// Trapezoid mean over the depths s in [0, 1].
double depth_mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (std::size_t k = 1; k < v.size(); ++k) sum += 0.5 * (v[k] + v[k - 1]);
  return sum / static_cast<double>(v.size() - 1);
}

}  // namespace

const char* basis_name(SurrogateBasis b) { return b == SurrogateBasis::plane ? "plane" : "quadric"; }

std::vector<double> surrogate_depths() {
  std::vector<double> s(kSurrogateDepths);
  for (int k = 0; k < kSurrogateDepths; ++k) s[k] = static_cast<double>(k) / (kSurrogateDepths - 1);
  return s;
}

// The solid fraction is fitted as logit(phi / kPhiCap): any fitted value maps back into
// (0, kPhiCap), so a film evaluated off the map's points (as the leave-one-out check does at a
// corner) stays a film. kPhiCap is the densest packing of equal spheres, pi / sqrt(18).
namespace {
constexpr double kPhiCap = 0.74048;
double phi_to_fit(double phi) {
  const double p = std::clamp(phi / kPhiCap, 1e-9, 1.0 - 1e-9);
  return std::log(p / (1.0 - p));
}
double phi_from_fit(double v) { return kPhiCap / (1.0 + std::exp(-v)); }
std::vector<double> phis_from_fit(const std::vector<double>& v) {
  std::vector<double> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = phi_from_fit(v[k]);
  return out;
}
}  // namespace

// The quantities whose leave-one-out error picks their basis and is reported: each maps a
// point's numbers (thickness, profiles; the solid fraction as fitted) to one figure.
namespace {
struct Quantity {
  const char* name;
  const char* unit;
  double (*figure)(const std::vector<double>& v, double particle_diameter);
};
const Quantity kQuantities[4] = {
    {"film thickness", "d", [](const std::vector<double>& v, double d) { return std::exp(v[0]) / d; }},
    {"surface velocity u(s = 1)", "m/s", [](const std::vector<double>& v, double) { return v.back(); }},
    {"depth-mean solid fraction", "-",
     [](const std::vector<double>& v, double) { return depth_mean(phis_from_fit(v)); }},
    {"depth-mean dispersion D", "m2/s", [](const std::vector<double>& v, double) { return depth_mean(v); }},
};
}  // namespace

FilmSurrogate::FilmSurrogate(std::vector<SurrogateSample> samples) : samples_(std::move(samples)) { fit_all(nullptr); }

FilmSurrogate::FilmSurrogate(std::vector<SurrogateSample> samples, SurrogateBasis t, SurrogateBasis u,
                             SurrogateBasis phi, SurrogateBasis D)
    : samples_(std::move(samples)) {
  const SurrogateBasis forced[4] = {t, u, phi, D};
  fit_all(forced);
}

void FilmSurrogate::fit_all(const SurrogateBasis* forced) {
  const std::size_t n = samples_.size();
  if (n < 3) throw std::invalid_argument("film surrogate: " + std::to_string(n) + " map point(s); it needs at least 3");
  const auto& f0 = samples_[0].film;
  const auto s = surrogate_depths();
  profiles_.clear();
  for (const auto& p : samples_) {
    const auto& f = p.film;
    f.check();
    if (!(p.speed_rpm > 0.0) || !(p.mass_flow > 0.0))
      throw std::invalid_argument("film surrogate: a map point at speed " + std::to_string(p.speed_rpm) +
                                  " rpm and mass flow " + std::to_string(p.mass_flow) + " kg/s");
    if (f.nz() != f0.nz() || std::abs(f.length - f0.length) > 1e-9 * f0.length ||
        std::abs(f.particle_diameter - f0.particle_diameter) > 1e-9 * f0.particle_diameter)
      throw std::invalid_argument(
          "film surrogate: the map's films differ in length, sections or particle size (one receiver per map)");
    // A slice's film is one section repeated along z; a drum's varies along z, which the
    // surrogate's numbers (one profile per point) do not hold.
    for (std::size_t i = 1; i < f.nz(); ++i)
      if (std::abs(f.t[i] - f.t[0]) > 1e-9 * f.t[0]) {
        char at[96];
        std::snprintf(at, sizeof at, "%.6g rpm, %.6g kg/s", p.speed_rpm, p.mass_flow);
        throw std::invalid_argument(std::string("film surrogate: the film at ") + at +
                                    " varies along z (a fed drum's); the surrogate fits slices' films, uniform "
                                    "along z");
      }
    Profiles pr;
    const double t = f.t[0];
    pr.log_t = std::log(t);
    for (double sk : s) {
      pr.u.push_back(f.sample(f.u, f.z[0], sk * t));
      pr.phi.push_back(phi_to_fit(f.sample(f.phi, f.z[0], sk * t)));
      pr.D.push_back(f.sample(f.D, f.z[0], sk * t));
    }
    profiles_.push_back(std::move(pr));
  }
  // Centre and spread of ln(speed) and ln(mass flow) over the map (spread 1 when constant:
  // the fit then finds the points on one line and refuses).
  double sx = 0, sy = 0, sxx = 0, syy = 0;
  for (const auto& p : samples_) {
    const double x = std::log(p.speed_rpm), y = std::log(p.mass_flow);
    sx += x, sy += y, sxx += x * x, syy += y * y;
  }
  const double nn = static_cast<double>(n);
  st_.x0 = sx / nn, st_.y0 = sy / nn;
  st_.sx = std::sqrt(std::max(0.0, sxx / nn - st_.x0 * st_.x0));
  st_.sy = std::sqrt(std::max(0.0, syy / nn - st_.y0 * st_.y0));
  if (!(st_.sx > 1e-12)) st_.sx = 1.0;
  if (!(st_.sy > 1e-12)) st_.sy = 1.0;
  std::vector<std::vector<double>> vals[4];
  for (const auto& pr : profiles_) {
    vals[0].push_back({pr.log_t});
    vals[1].push_back(pr.u);
    vals[2].push_back(pr.phi);
    vals[3].push_back(pr.D);
  }
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  Fit* fits[4] = {&t_, &u_, &phi_, &D_};
  const double d = f0.particle_diameter;
  for (int q = 0; q < 4; ++q) {
    SurrogateBasis pick = SurrogateBasis::plane;
    if (forced) {
      pick = forced[q];
    } else if (n >= kQuadricMinimumPoints) {
      // The basis with the smaller leave-one-out RMS of the quantity's figure.
      double best = std::numeric_limits<double>::infinity();
      for (SurrogateBasis b : {SurrogateBasis::plane, SurrogateBasis::quadric}) {
        double sum = 0.0;
        bool ok = true;
        for (std::size_t i = 0; i < n && ok; ++i) {
          std::vector<std::size_t> rest;
          for (std::size_t j = 0; j < n; ++j)
            if (j != i) rest.push_back(j);
          const auto c = least_squares(b, st_, samples_, vals[q], rest);
          if (c.empty()) {
            ok = false;
            break;
          }
          const double e = kQuantities[q].figure(evaluate(b, st_, c, samples_[i].speed_rpm, samples_[i].mass_flow), d) -
                           kQuantities[q].figure(vals[q][i], d);
          sum += e * e;
        }
        if (ok && sum < best) best = sum, pick = b;
      }
    }
    fits[q]->basis = pick;
    fits[q]->coef = least_squares(pick, st_, samples_, vals[q], all);
    if (fits[q]->coef.empty())
      throw std::invalid_argument(std::string("film surrogate: the map's points do not determine a ") +
                                  basis_name(pick) +
                                  " in ln(speed) and ln(mass flow) (they must span both, not lie on one line)");
  }
}

thermal::FilmField FilmSurrogate::film_at(double speed_rpm, double mass_flow) const {
  if (!(speed_rpm > 0.0) || !(mass_flow > 0.0))
    throw std::invalid_argument("film surrogate: speed and mass flow must be > 0");
  const auto& f0 = samples_[0].film;
  thermal::FilmField f;
  f.z = f0.z;
  f.drum_diameter = f0.drum_diameter;
  f.length = f0.length;
  f.particle_diameter = f0.particle_diameter;
  f.omega = speed_rpm * 2.0 * kPi / 60.0;
  f.mdot = mass_flow;
  f.scaling = "film surrogate of " + std::to_string(samples_.size()) + " map points (docs/operating.md)";
  const double t = std::exp(evaluate(t_.basis, st_, t_.coef, speed_rpm, mass_flow)[0]);
  const auto u = evaluate(u_.basis, st_, u_.coef, speed_rpm, mass_flow);
  const auto phi = evaluate(phi_.basis, st_, phi_.coef, speed_rpm, mass_flow);
  const auto D = evaluate(D_.basis, st_, D_.coef, speed_rpm, mass_flow);
  for (double sk : surrogate_depths()) f.eta.push_back(sk * t);
  f.t.assign(f.nz(), t);
  for (std::size_t i = 0; i < f.nz(); ++i)
    for (int k = 0; k < kSurrogateDepths; ++k) {
      f.u.push_back(std::max(0.0, u[k]));
      f.phi.push_back(phi_from_fit(phi[k]));
      f.D.push_back(std::max(0.0, D[k]));
    }
  return f;
}

FilmSurrogate FilmSurrogate::without(std::size_t i) const {
  std::vector<SurrogateSample> rest;
  for (std::size_t j = 0; j < samples_.size(); ++j)
    if (j != i) rest.push_back(samples_[j]);
  const bool quadric_fits = rest.size() >= kQuadricMinimumPoints;
  auto keep = [&](SurrogateBasis b) { return quadric_fits ? b : SurrogateBasis::plane; };
  return FilmSurrogate(std::move(rest), keep(t_.basis), keep(u_.basis), keep(phi_.basis), keep(D_.basis));
}

std::vector<SurrogateError> FilmSurrogate::leave_one_out() const {
  const std::size_t n = samples_.size();
  if (n < 4) throw std::invalid_argument("film surrogate: a leave-one-out check needs at least 4 map points");
  const Fit* fits[4] = {&t_, &u_, &phi_, &D_};
  const double d = samples_[0].film.particle_diameter;
  std::vector<SurrogateError> out(4);
  double lo[4], hi[4], sum[4] = {0.0, 0.0, 0.0, 0.0};
  for (int q = 0; q < 4; ++q) {
    out[q].quantity = kQuantities[q].name;
    out[q].unit = kQuantities[q].unit;
    out[q].basis = fits[q]->basis;
    lo[q] = std::numeric_limits<double>::infinity(), hi[q] = -lo[q];
  }
  // One refit per point left out serves all four quantities.
  for (std::size_t i = 0; i < n; ++i) {
    const FilmSurrogate rest = without(i);
    const Fit* rf[4] = {&rest.t_, &rest.u_, &rest.phi_, &rest.D_};
    const std::vector<double> log_t = {profiles_[i].log_t};
    const std::vector<double>* mine[4] = {&log_t, &profiles_[i].u, &profiles_[i].phi, &profiles_[i].D};
    for (int q = 0; q < 4; ++q) {
      const double truth = kQuantities[q].figure(*mine[q], d);
      const double guess = kQuantities[q].figure(
          evaluate(rf[q]->basis, rest.st_, rf[q]->coef, samples_[i].speed_rpm, samples_[i].mass_flow), d);
      sum[q] += (guess - truth) * (guess - truth);
      out[q].max_abs = std::max(out[q].max_abs, std::abs(guess - truth));
      lo[q] = std::min(lo[q], truth), hi[q] = std::max(hi[q], truth);
    }
  }
  for (int q = 0; q < 4; ++q) {
    out[q].rms = std::sqrt(sum[q] / static_cast<double>(n));
    out[q].range = hi[q] - lo[q];
  }
  return out;
}

}  // namespace centrec::coupling
