#include "film_operator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "air_conductivity.hpp"
#include "cavity_convection.hpp"
#include "physical_constants.hpp"
#include "solar_extinction.hpp"

namespace centrec::thermal {

namespace {
// van Leer limited slope from the backward (a) and forward (b) differences: second order
// where smooth, zero at extrema, so the face value stays between its neighbours.
double van_leer(double a, double b) { return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; }
double harmonic(double a, double b) { return 2.0 * a * b / (a + b); }
constexpr double kPi = 3.14159265358979323846;
}  // namespace

FilmOperator::FilmOperator(const FilmField& film, const FilmModel& model, const FilmGridSpec& spec)
    : grid_(build_film_grid(film, spec, model.material.rho_s)), model_(model), advection_(spec.advection) {
  model_.flux.check();
  model_.flux_time.check();
  model_.flow_time.check();
  // The bed model shares the particle parameters with the material (one source of truth).
  model_.bed.k_s = model_.material.k_s;
  model_.bed.epsilon = model_.material.epsilon;
  model_.bed.d = model_.material.d;
  const Material& m = model_.material;
  if (!(m.rho_s > 0 && m.k_s > 0 && m.d > 0)) throw std::invalid_argument("material: rho_s, k_s and d must be > 0");
  if (!(m.alpha >= 0 && m.alpha <= 1 && m.epsilon > 0 && m.epsilon <= 1))
    throw std::invalid_argument("material: alpha must be in [0, 1] and epsilon in (0, 1]");
  if (!(model_.T_in > 0)) throw std::invalid_argument("inlet temperature must be > 0 K");
  if (model_.flux.aperture_mean > 0.0) {
    // The flux given through the aperture: the same power spread uniformly over the film,
    // q_film = q_aperture A_aperture / A_film (docs/cavity_model.md, "Two bands").
    if (!model_.cavity.enabled)
      throw std::invalid_argument("a flux given at the aperture (flux.q_aperture) needs the cavity model: the open "
                                  "surface has no aperture");
    model_.flux.q = model_.flux.aperture_mean * aperture_area() / film_area();
  }
  const double spill = model_.cavity.spillage;
  if (spill != 0.0 && !(model_.cavity.enabled && spill > 0.0 && spill < 1.0))
    throw std::invalid_argument("spillage must be in [0, 1) and needs the cavity model (it lands on the front plate)");
  q_column_.resize(grid_.nz);
  // What enters: the case's flux less the spilled share (1 - 0 changes no arithmetic).
  for (int i = 0; i < grid_.nz; ++i) q_column_[i] = model_.flux.at(grid_.zc[i]) * (1.0 - spill);
  props_.resize(size());
  const double ext = model_.surface.extinction_depth_d;
  if (ext < 0.0 && model_.surface.extinction_local) {
    // Each cell's own phi: the optical depth accumulates through the loose top
    // (thermal/solar_extinction.hpp).
    local_share_.resize(size());
    std::vector<double> phi(grid_.nxi);
    for (int i = 0; i < grid_.nz; ++i) {
      for (int j = 0; j < grid_.nxi; ++j) phi[j] = grid_.phi[grid_.index(i, j)];
      const std::vector<double> s = local_extinction_shares(phi, grid_.deta[i], m.d, model_.surface.extinction_scale);
      for (int j = 0; j < grid_.nxi; ++j) local_share_[grid_.index(i, j)] = s[j];
    }
  } else if (ext != 0.0) {
    // Exponential solar absorption: depth n d per column (n from the column's mean phi if < 0).
    for (int i = 0; i < grid_.nz; ++i) {
      double n = ext;
      if (n < 0) {
        double phi = 0.0;
        for (int j = 0; j < grid_.nxi; ++j) phi += grid_.phi[grid_.index(i, j)] / grid_.nxi;
        n = extinction_depth_d_from_phi(phi);
      }
      extinction_depth_.push_back(model_.surface.extinction_scale * n * m.d);
    }
  }
  if (model_.film_top.two_flux) setup_film_top();
  if (model_.cavity.enabled) setup_cavity();
}

void FilmOperator::setup_film_top() {
  const FilmTopRadiation& ft = model_.film_top;
  if (grid_.lumped) throw std::invalid_argument("film_top two_flux needs the 2d model (a depth to radiate through)");
  if (!model_.cavity.enabled && model_.surface.loss_factor != 1.0)
    throw std::invalid_argument("film_top two_flux: the open surface's loss factor must be 1 (the film's own "
                                "emissivity follows from the two-flux column)");
  if (!(ft.depth_d > 0.0)) throw std::invalid_argument("film_top two_flux: depth_d must be > 0");
  // The zone's cells absorb and emit by their own solid fraction; sunlight laid by any other
  // rule (the column's mean phi, a fixed depth, the top cell) lands in near-empty top cells
  // that can neither hold nor re-emit it (a fed drum's loose top reached 2487 K,
  // docs/slice_vs_drum_thermal.md).
  if (!solar_by_local_phi(model_.surface))
    throw std::invalid_argument(
        "film_top two_flux takes the sunlight by each cell's own solid fraction: give thermal.flux.absorption "
        "extinction with extinction_phi local (no extinction_depth_d)");
  const Material& m = model_.material;
  const double b = diffuse_sphere_backscatter_fraction();
  const int nxi = grid_.nxi;
  top_begin_.resize(grid_.nz);
  top_.reserve(grid_.nz);
  for (int i = 0; i < grid_.nz; ++i) {
    // The zone: the cells whose centre lies within depth_d particle diameters of the surface
    // (at least the top cell).
    const double deta = grid_.deta[i];
    int j0 = nxi - 1;
    while (j0 > 0 && grid_.tc[i] - (j0 - 0.5) * deta < ft.depth_d * m.d) --j0;
    top_begin_[i] = j0;
    std::vector<double> phi(nxi - j0);
    for (int j = j0; j < nxi; ++j) phi[j - j0] = grid_.phi[grid_.index(i, j)];
    top_.push_back(two_flux_column(phi, deta, m.d, m.epsilon, b));
  }
}

double FilmOperator::top_irradiation(int i) const {
  return cavity_ ? cavity_->H[cavity_->ring_of[i]] : kStefanBoltzmann * std::pow(model_.surface.T_env, 4);
}

namespace {
double emissive_power(double T) { return kStefanBoltzmann * T * T * T * T; }
}  // namespace

double FilmOperator::top_absorbed(int i, int j, const double* T, double H) const {
  const TwoFluxColumn& c = top_[i];
  const int j0 = top_begin_[i], n = c.n, ns = n + 2, base = i * grid_.nxi, below = top_below(i);
  double q = 0.0;
  auto add_row = [&](const double* row) {
    double s = row[n] * emissive_power(T[base + below]) + row[n + 1] * H;
    for (int k = 0; k < n; ++k) s += row[k] * emissive_power(T[base + j0 + k]);
    q += s;
  };
  if (j >= j0) add_row(&c.absorbed[static_cast<std::size_t>(j - j0) * ns]);
  if (j == below) add_row(c.below.data());
  return q;
}

double FilmOperator::top_escaping(int i, const double* T) const {
  const TwoFluxColumn& c = top_[i];
  const int j0 = top_begin_[i], n = c.n, base = i * grid_.nxi;
  double s = c.leaving[n] * emissive_power(T[base + top_below(i)]);
  for (int k = 0; k < n; ++k) s += c.leaving[k] * emissive_power(T[base + j0 + k]);
  return s;
}

double FilmOperator::top_net_emitted(int i, const double* T, double H) const {
  return top_escaping(i, T) - top_[i].emissivity() * H;
}

double FilmOperator::film_area() const { return grid_.perimeter * grid_.length; }

double FilmOperator::aperture_area() const {
  if (!model_.cavity.enabled) return 0.0;
  // The aperture at z = L: a disc of aperture_diameter, by default the film's drum diameter.
  const double R = grid_.perimeter / (2.0 * kPi);
  const double ra = model_.cavity.aperture_diameter > 0 ? std::min(0.5 * model_.cavity.aperture_diameter, R) : R;
  return kPi * ra * ra;
}

std::vector<double> FilmOperator::cavity_surface_z() const {
  if (!cavity_) return {};
  const Cavity& c = *cavity_;
  std::vector<double> z(c.n, grid_.length);  // the front annulus, if any, at the aperture end
  for (int k = 0; k < c.rings; ++k)
    z[k] = 0.5 * grid_.length * (c.ring_begin[k] + c.ring_begin[k + 1]) / grid_.nz;
  if (c.rings < c.n) z[c.rings] = 0.0;  // the back plate
  return z;
}

void FilmOperator::setup_cavity() {
  const CavitySettings& cs = model_.cavity;
  const Material& mat = model_.material;
  if (!(mat.alpha > 0.0)) throw std::invalid_argument("cavity model: the film's solar absorptance must be > 0");
  if (!(cs.wall_absorptance > 0 && cs.wall_absorptance <= 1 && cs.wall_emissivity > 0 && cs.wall_emissivity <= 1))
    throw std::invalid_argument("cavity model: wall absorptance and emissivity must be in (0, 1]");
  auto c = std::make_unique<Cavity>();
  const int nz = grid_.nz, nr = std::clamp(cs.rings, 1, nz);
  c->rings = nr;
  c->ring_begin.resize(nr + 1);
  for (int k = 0; k <= nr; ++k) c->ring_begin[k] = static_cast<int>((static_cast<long>(k) * nz) / nr);
  c->ring_of.resize(nz);
  std::vector<double> z(nr + 1);
  for (int k = 0; k < nr; ++k) {
    z[k] = grid_.length * c->ring_begin[k] / nz;
    for (int i = c->ring_begin[k]; i < c->ring_begin[k + 1]; ++i) c->ring_of[i] = k;
  }
  z[nr] = grid_.length;
  const double R = grid_.perimeter / (2.0 * kPi);
  const double ra = cs.aperture_diameter > 0 ? 0.5 * cs.aperture_diameter : R;
  if (ra > R * (1 + 1e-9))
    throw std::invalid_argument("cavity model: the aperture diameter exceeds the drum diameter");
  const CavityViewFactors vf = cavity_view_factors(R, z, std::min(ra, R));
  const int n = vf.size() - 1;
  c->n = n;
  c->area.assign(vf.area.begin(), vf.area.begin() + n);
  std::vector<double> rho_solar(n), rho_thermal(n);
  c->eps.resize(n);
  const double U_wall = model_.wall.adiabatic ? 0.0 : model_.wall.U_w;
  for (int k = 0; k < n; ++k) {
    const bool ring = k < nr, plate = k == vf.annulus();
    double alpha = mat.alpha;
    c->eps[k] = mat.epsilon;
    if (ring && two_flux()) {
      // The ring's diffuse emissivity: the mean of its columns' two-flux emissivities, so that
      // the ring's emission eps_k E_k is the mean of what its columns' tops emit.
      double e = 0.0;
      for (int i = c->ring_begin[k]; i < c->ring_begin[k + 1]; ++i) e += top_[i].emissivity();
      c->eps[k] = e / (c->ring_begin[k + 1] - c->ring_begin[k]);
    }
    if (!ring) {
      alpha = plate && cs.plate_absorptance >= 0 ? cs.plate_absorptance : cs.wall_absorptance;
      c->eps[k] = plate && cs.plate_emissivity >= 0 ? cs.plate_emissivity : cs.wall_emissivity;
      c->wall_alpha.push_back(alpha);
      c->wall_U.push_back(plate && cs.plate_U >= 0 ? cs.plate_U : U_wall);
      if (!(alpha > 0 && alpha <= 1 && c->eps[k] > 0 && c->eps[k] <= 1))
        throw std::invalid_argument("cavity model: front plate absorptance and emissivity must be in (0, 1]");
    }
    rho_solar[k] = 1.0 - alpha;
    rho_thermal[k] = 1.0 - c->eps[k];
  }
  c->thermal = std::make_unique<CavityEnclosure>(vf, rho_thermal);
  c->thermal->irradiation_map(c->eps, c->M, c->m);
  c->solar = std::make_unique<CavityEnclosure>(vf, rho_solar);
  c->primary.assign(n, 0.0);
  for (int k = 0; k < nr; ++k) {
    const int b = c->ring_begin[k], e = c->ring_begin[k + 1];
    for (int i = b; i < e; ++i) c->primary[k] += q_column_[i] / (e - b);
  }
  const BandSolution sol = c->solar->solve(std::vector<double>(n, 0.0), c->primary, 0.0);
  c->H_solar = sol.H;
  c->solar_out = sol.aperture_out;
  c->H.assign(n, 0.0);
  c->E.assign(n, 0.0);
  c->T_s.assign(nz, model_.T_in);
  c->T_wall.assign(n - nr, model_.T_in);
  cavity_ = std::move(c);
}

double FilmOperator::solar_irradiation(int i, const Inputs& in) const {
  const double diffuse = cavity_ ? cavity_->H_solar[cavity_->ring_of[i]] : 0.0;
  return (q_column_[i] + diffuse) * in.flux_factor;
}

void FilmOperator::update_cavity(const double* T, const Inputs& in) {
  Cavity& c = *cavity_;
  const int nz = grid_.nz, nxi = grid_.nxi, nr = c.rings, n = c.n;
  const SurfaceConditions& s = model_.surface;
  const WallConditions& w = model_.wall;
  const CavitySettings& cs = model_.cavity;
  const double sigma = kStefanBoltzmann, E_env = sigma * std::pow(s.T_env, 4);
  const double D = grid_.perimeter / kPi, d_ap = cs.aperture_diameter > 0 ? cs.aperture_diameter : D;
  for (int i = 0; i < nz; ++i) c.T_s[i] = T[i * nxi + nxi - 1];
  // Fixed point: the film surface temperatures follow the irradiation through the stiff
  // half-cell conduction (contraction ~ 4 eps sigma T^3 / (2 k / deta) << 1); the walls
  // are in radiative equilibrium with the film.
  for (int it = 0; it < 200; ++it) {
    double area_T = 0.0, area = 0.0;
    for (int k = 0; k < n; ++k) {
      double E = 0.0, Tm = 0.0;
      if (k < nr) {
        const int b = c.ring_begin[k], e = c.ring_begin[k + 1];
        for (int i = b; i < e; ++i) {
          const double x = c.T_s[i];
          // Two-flux top: what the column's top emits (independent of H), over the ring's emissivity.
          E += (two_flux() ? top_escaping(i, T) / c.eps[k] : sigma * x * x * x * x) / (e - b);
          Tm += x / (e - b);
        }
      } else {
        const double x = c.T_wall[k - nr];
        E = sigma * x * x * x * x;
        Tm = x;
      }
      c.E[k] = E;
      area_T += c.area[k] * Tm;
      area += c.area[k];
    }
    if (cs.convection_correlation) {
      c.convection = cavity_mixed_convection(area_T / area, s.T_air, D, d_ap, cs.tilt_rad, cs.wind_speed,
                                             cs.rotation_rad_s, cs.mixing_exponent);
      c.h = cs.convection_scale * c.convection.h;
    } else {
      c.h = s.h_conv;
    }
    for (int k = 0; k < n; ++k) {
      double h = c.m[k] * E_env;
      const double* Mk = &c.M[static_cast<std::size_t>(k) * n];
      for (int j = 0; j < n; ++j) h += Mk[j] * c.E[j];
      c.H[k] = h;
    }
    double change = 0.0;
    for (int i = 0; i < nz; ++i) {
      const int top = i * nxi + nxi - 1;
      const double Ts = surface(i, T[top], props_[top].kn, in).T_s;
      change = std::max(change, std::abs(Ts - c.T_s[i]) / Ts);
      c.T_s[i] = Ts;
    }
    for (int k = nr; k < n; ++k) {
      // a S + e H - e sigma x^4 - h (x - T_air) - U (x - T_amb) = 0: concave and decreasing in
      // x, so Newton from above the root (where e sigma x^4 equals all gains) converges
      // monotonically.
      const double e = c.eps[k], S = c.wall_alpha[k - nr] * c.H_solar[k] * in.flux_factor, U = c.wall_U[k - nr];
      const double gain = S + e * c.H[k] + c.h * s.T_air + U * w.T_amb;
      double x = std::pow(gain / (e * sigma), 0.25);
      for (int iter = 0; iter < 100; ++iter) {
        const double g = gain - e * sigma * x * x * x * x - (c.h + U) * x;
        const double dx = g / (4.0 * e * sigma * x * x * x + c.h + U);
        x += dx;
        if (std::abs(dx) <= 1e-15 * x) break;
      }
      change = std::max(change, std::abs(x - c.T_wall[k - nr]) / x);
      c.T_wall[k - nr] = x;
    }
    if (change < 1e-13) break;
  }
}

long FilmOperator::lower_bandwidth() const {
  return advection_ == Advection::van_leer ? 2L * grid_.nxi : grid_.nxi;
}

FilmOperator::Inputs FilmOperator::inputs_at(double t) const {
  const double ti = frozen_ ? 0.0 : t;
  return {model_.flux_time.at(ti), model_.flow_time.at(ti), t};
}

double FilmOperator::k_bed(int p, double T) const {
  const double kc = model_.conductivity.k_constant;
  if (kc > 0) return kc;
  if (in_top_zone(p)) {
    // The two-flux zone carries the radiation itself: no k_rad; below ZBS's range of solid
    // fraction, Maxwell's conduction of dispersed spheres (thermal/film_top_radiation.hpp).
    const double phi = grid_.phi[p];
    if (phi < model_.film_top.zbs_min_phi)
      return maxwell_dispersion_conductivity(model_.material.k_s, air_conductivity(std::max(T, 1.0)), phi);
    BedConductivityModel no_rad = model_.bed;
    no_rad.radiation = false;
    return no_rad.k_bed(T, phi);
  }
  return model_.bed.k_bed(T, grid_.phi[p]);
}

double FilmOperator::k_mix(int p, double T) const {
  return grid_.phi[p] * model_.material.rho_s * model_.heat.cp(T) * grid_.D[p];
}

FilmOperator::CellProps FilmOperator::props(int p, double T) const {
  const auto& c = model_.conductivity;
  CellProps pr;
  pr.cp = model_.heat.cp(T);
  pr.h = model_.heat.enthalpy(T);
  const double kb = k_bed(p, T);
  pr.kn = c.mixing ? kb + grid_.phi[p] * model_.material.rho_s * pr.cp * grid_.D[p] : kb;
  pr.kz = c.axial == ConductivitySettings::Axial::none ? 0.0
          : c.axial == ConductivitySettings::Axial::bed ? kb
                                                         : pr.kn;
  pr.capacity = model_.material.rho_s * grid_.phi[p] * pr.cp * grid_.volume(p / grid_.nxi);
  return pr;
}

double FilmOperator::face_temperature(int f, int j, const double* T) const {
  // Axial face f lies between cells f-1 and f; the flow is toward +z (u >= 0), so the
  // upwind cell is f-1.
  const int nxi = grid_.nxi, i = f - 1;
  const double Ti = T[i * nxi + j];
  if (advection_ == Advection::upwind) return Ti;
  // Ghost upstream of the first cell: T_in on the inlet face -> T_{-1} = 2 T_in - T_0.
  const double Tm = i > 0 ? T[(i - 1) * nxi + j] : 2.0 * model_.T_in - Ti;
  const double a = Ti - Tm;
  const double b = i + 1 < grid_.nz ? T[(i + 1) * nxi + j] - Ti : a;  // outlet: extrapolate
  return Ti + 0.5 * van_leer(a, b);
}

FilmOperator::SurfaceState FilmOperator::surface(int i, double T_p, double kn, const Inputs& in) const {
  const auto& s = model_.surface;
  const Cavity* c = cavity_.get();
  // Open surface: eps sigma F (T^4 - T_env^4). Cavity: eps (sigma T^4 - H) with H the
  // thermal irradiation of the column's ring.
  const double F = c ? 1.0 : s.loss_factor;
  // Two-flux top: the thermal band is exchanged by the zone's cells, not at this surface.
  const double eps_sigma_F = two_flux() ? 0.0 : model_.material.epsilon * kStefanBoltzmann * F;
  const double E_in = c ? c->H[c->ring_of[i]] : kStefanBoltzmann * std::pow(s.T_env, 4);
  const double absorbed_in = two_flux() ? 0.0 : model_.material.epsilon * F * E_in;
  const double h = c ? c->h : s.h_conv;
  SurfaceState st;
  const double Aq = volumetric() ? 0.0 : model_.material.alpha * solar_irradiation(i, in);
  st.absorbed = Aq;
  if (grid_.lumped) {
    st.T_s = T_p;
  } else {
    // Local balance kk (T_s - T_p) = Aq - eps sigma F T_s^4 + eps F E_in - h (T_s - T_air):
    // g(T_s) is increasing and convex, and g >= 0 at the start point, so Newton converges
    // monotonically from above.
    const double kk = 2.0 * kn / grid_.deta[i];
    auto g = [&](double x) { return kk * (x - T_p) + eps_sigma_F * x * x * x * x - absorbed_in + h * (x - s.T_air) - Aq; };
    double x = std::max({T_p, std::pow(E_in / kStefanBoltzmann, 0.25), s.T_air}) + Aq / (kk + h);
    for (int it = 0; it < 100; ++it) {
      const double dg = kk + 4.0 * eps_sigma_F * x * x * x + h;
      const double dx = g(x) / dg;
      x -= dx;
      if (std::abs(dx) <= 1e-14 * x) break;
    }
    st.T_s = x;
  }
  const double Ts = st.T_s;
  st.emitted = eps_sigma_F * Ts * Ts * Ts * Ts - absorbed_in;
  st.convected = h * (Ts - s.T_air);
  return st;
}

double FilmOperator::wall_loss(int i, double T_p, double kn) const {
  const auto& w = model_.wall;
  if (w.adiabatic) return 0.0;
  if (grid_.lumped) return w.U_w * (T_p - w.T_amb);
  return (T_p - w.T_amb) / (1.0 / w.U_w + 0.5 * grid_.deta[i] / kn);
}

double FilmOperator::absorbed_share(int i, int j) const {
  if (!local_share_.empty()) return local_share_[grid_.index(i, j)];
  if (!extinction_depth_.empty()) {
    // Beer-Lambert below the surface, normalised over the film depth.
    const double t = grid_.tc[i], dl = extinction_depth_[i];
    const double lo = j * grid_.deta[i], hi = (j + 1) * grid_.deta[i];
    return std::exp(-(t - hi) / dl) * -std::expm1(-(hi - lo) / dl) / -std::expm1(-t / dl);
  }
  const double layers = model_.surface.absorb_depth_layers;
  if (!(layers > 0)) return 0.0;
  const double t = grid_.tc[i];
  const double depth = std::min(layers * model_.material.d, t);
  const double lo = std::max(j * grid_.deta[i], t - depth), hi = (j + 1) * grid_.deta[i];
  return hi > lo ? (hi - lo) / depth : 0.0;
}

double FilmOperator::cell_residual(int p, const double* T, const CellProps* pr, const Inputs& in) const {
  const FilmGrid& g = grid_;
  const int nxi = g.nxi, nz = g.nz, i = p / nxi, j = p % nxi;
  const double s = in.flow_factor;
  const CellProps& P = pr[p];
  const double Tp = T[p];
  double R = 0.0;
  // West face (inflow).
  if (i == 0) {
    R += s * g.m_axial[j] * model_.heat.enthalpy(model_.T_in);
    R += P.kz * (g.tf[0] / nxi) * (model_.T_in - Tp) / (0.5 * g.dz);
  } else {
    const int w = p - nxi;
    R += s * g.m_axial[i * nxi + j] * model_.heat.enthalpy(face_temperature(i, j, T));
    if (P.kz > 0) R += harmonic(pr[w].kz, P.kz) * 0.5 * (g.deta[i - 1] + g.deta[i]) * (T[w] - Tp) / g.dz;
  }
  // East face (outflow).
  R -= s * g.m_axial[(i + 1) * nxi + j] *
       (advection_ == Advection::upwind ? P.h : model_.heat.enthalpy(face_temperature(i + 1, j, T)));
  if (i + 1 < nz) {
    const int e = p + nxi;
    if (P.kz > 0) R += harmonic(pr[e].kz, P.kz) * 0.5 * (g.deta[i + 1] + g.deta[i]) * (T[e] - Tp) / g.dz;
  }
  // Bottom face: the wall, or the cell below.
  if (j == 0) {
    R -= wall_loss(i, Tp, P.kn) * g.dz;
  } else {
    const int b = p - 1;
    const double W = s * g.m_xi[i * (nxi + 1) + j];
    R += W * (W > 0 ? pr[b].h : P.h);
    R += harmonic(pr[b].kn, P.kn) * g.dz * (T[b] - Tp) / g.deta[i];
  }
  // Top face: the free surface, or the cell above.
  if (j == nxi - 1) {
    const SurfaceState st = surface(i, Tp, P.kn, in);
    R += (st.absorbed - st.emitted - st.convected) * g.dz;
  } else {
    const int a = p + 1;
    const double W = s * g.m_xi[i * (nxi + 1) + j + 1];
    R -= W * (W > 0 ? P.h : pr[a].h);
    R += harmonic(pr[a].kn, P.kn) * g.dz * (T[a] - Tp) / g.deta[i];
  }
  // Volumetric absorption over the first particle layers, and an optional source.
  const double share = absorbed_share(i, j);
  if (share > 0) R += share * model_.material.alpha * solar_irradiation(i, in) * g.dz;
  if (two_flux() && j >= top_below(i)) R += top_absorbed(i, j, T, top_irradiation(i)) * g.dz;
  if (model_.source) R += model_.source(g.zc[i], g.eta_center(i, j), in.t) * g.volume(i);
  return R;
}

bool FilmOperator::rhs(double t, const double* y, double* ydot) {
  const long n = size();
  for (long p = 0; p < n; ++p)
    if (!(y[p] > 0.0) || !std::isfinite(y[p])) return false;
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  if (cavity_) update_cavity(y, in);
  for (long p = 0; p < n; ++p) ydot[p] = cell_residual(static_cast<int>(p), y, props_.data(), in) / props_[p].capacity;
  return true;
}

bool FilmOperator::jacobian(double t, const double* y, const double*, const BandEntrySink& sink) {
  // Finite differences column by column, re-evaluating only the rows in the column's
  // stencil: the colored finite-difference Jacobian specialised to the known sparsity
  // (cost ~ 6 cell residuals per unknown instead of (ml + mu + 1) full right-hand sides).
  const long n = size();
  const int nxi = grid_.nxi, nz = grid_.nz;
  std::vector<double>& f0 = jac_scratch_;
  f0.resize(n);
  if (!rhs(t, y, f0.data())) return false;
  std::vector<double> T(y, y + n);
  const Inputs in = inputs_at(t);
  std::vector<int> rows_buffer(6 + nxi);
  int* rows = rows_buffer.data();
  for (long l = 0; l < n; ++l) {
    const int i = static_cast<int>(l) / nxi, j = static_cast<int>(l) % nxi;
    int nr = 0;
    if (two_flux() && j >= top_below(i)) {
      // The zone's cells and the cell below it all see each other's emission.
      for (int k = top_below(i); k < nxi; ++k)
        if (k < j - 1 || k > j + 1) rows[nr++] = i * nxi + k;
    }
    rows[nr++] = static_cast<int>(l);
    if (j > 0) rows[nr++] = static_cast<int>(l) - 1;
    if (j + 1 < nxi) rows[nr++] = static_cast<int>(l) + 1;
    if (i > 0) rows[nr++] = static_cast<int>(l) - nxi;
    if (i + 1 < nz) rows[nr++] = static_cast<int>(l) + nxi;
    if (advection_ == Advection::van_leer && i + 2 < nz) rows[nr++] = static_cast<int>(l) + 2 * nxi;
    std::sort(rows, rows + nr);  // the OdeSystem contract: rows increasing within a column
    const double Tl = T[l];
    const CellProps saved = props_[l];
    const double dT = 1.5e-8 * std::max(std::abs(Tl), 1.0);
    T[l] = Tl + dT;
    props_[l] = props(static_cast<int>(l), T[l]);
    for (int r = 0; r < nr; ++r) {
      const int row = rows[r];
      const double f = cell_residual(row, T.data(), props_.data(), in) / props_[row].capacity;
      sink(row, l, (f - f0[row]) / dT);
    }
    T[l] = Tl;
    props_[l] = saved;
  }
  return true;
}

double FilmOperator::residual_scale(const Inputs& in) const {
  // The absorbed power, at least the power of a 1 K rise of the flow. Without flux, the
  // power the flow carries above its coldest surroundings (what it can lose): a 1 K scale
  // there asks the residual to resolve below the round-off of the losses. props_ must hold
  // the current state's props.
  double scale = 0.0;
  for (int i = 0; i < grid_.nz; ++i) scale += model_.material.alpha * q_column_[i] * in.flux_factor * grid_.dz;
  const double sink = std::min({model_.surface.T_env, model_.surface.T_air, model_.wall.T_amb});
  const double dT = scale > 0.0 ? 1.0 : std::max(1.0, model_.T_in - sink);
  scale = std::max(scale, grid_.mass_flux * in.flow_factor * model_.heat.cp(model_.T_in) * dT);
  if (!(scale > 0.0)) {
    // Neither flux nor flow (a resting film with sources): heating the film by 1 K over
    // its conduction time.
    double capacity = 0.0;
    for (long p = 0; p < size(); ++p) capacity += props_[p].capacity;
    scale = capacity / time_scale();
  }
  return scale;
}

double FilmOperator::steady_residual(double t, const double* y) {
  const long n = size();
  for (long p = 0; p < n; ++p)
    if (!(y[p] > 0.0) || !std::isfinite(y[p])) return INFINITY;
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  if (cavity_) update_cavity(y, in);
  double sum = 0.0;
  for (long p = 0; p < n; ++p) sum += std::abs(cell_residual(static_cast<int>(p), y, props_.data(), in));
  return sum / residual_scale(in);
}

double FilmOperator::steady_residual_floor(double t, const double* y) {
  // A temperature is known to half an ulp, ~1.1e-16 T, so a cell's residual cannot be
  // brought below its conductance to all neighbours and boundaries (conduction, the
  // advected c_p m of every face, wall, surface) times that: sum over cells of
  // eps_machine T_p G_p over the same scale as steady_residual. It grows with the
  // conductivity and the cell count (G ~ k dz / deta); at the design point it is ~1e-12.
  const long n = size();
  for (long p = 0; p < n; ++p)
    if (!(y[p] > 0.0) || !std::isfinite(y[p])) return 0.0;
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  const FilmGrid& g = grid_;
  const int nxi = g.nxi, nz = g.nz;
  const double s = in.flow_factor;
  const auto& sf = model_.surface;
  const double radiative = 4.0 * model_.material.epsilon * kStefanBoltzmann * (cavity_ ? 1.0 : sf.loss_factor);
  const double h = cavity_ ? cavity_->h : sf.h_conv;
  double sum = 0.0;
  for (long p = 0; p < n; ++p) {
    const int i = static_cast<int>(p) / nxi, j = static_cast<int>(p) % nxi;
    const CellProps& P = props_[p];
    double G = s * (g.m_axial[i * nxi + j] + g.m_axial[(i + 1) * nxi + j]) * P.cp;
    if (P.kz > 0) {
      G += i == 0 ? P.kz * (g.tf[0] / nxi) / (0.5 * g.dz)
                  : harmonic(props_[p - nxi].kz, P.kz) * 0.5 * (g.deta[i - 1] + g.deta[i]) / g.dz;
      if (i + 1 < nz) G += harmonic(props_[p + nxi].kz, P.kz) * 0.5 * (g.deta[i + 1] + g.deta[i]) / g.dz;
    }
    if (j == 0) {
      if (!model_.wall.adiabatic) G += g.dz / (1.0 / model_.wall.U_w + (g.lumped ? 0.0 : 0.5 * g.deta[i] / P.kn));
    } else {
      G += s * std::abs(g.m_xi[i * (nxi + 1) + j]) * P.cp + harmonic(props_[p - 1].kn, P.kn) * g.dz / g.deta[i];
    }
    const double Tp = y[p];
    if (two_flux() && j >= top_begin_[i]) {
      const TwoFluxColumn& c = top_[i];
      G += std::abs(c.absorbed[static_cast<std::size_t>(j - top_begin_[i]) * (c.n + 2) + j - top_begin_[i]]) * 4.0 *
           kStefanBoltzmann * Tp * Tp * Tp * g.dz;
    }
    if (j == nxi - 1) {
      G += ((two_flux() ? 0.0 : radiative * Tp * Tp * Tp) + h) * g.dz;
    } else {
      G += s * std::abs(g.m_xi[i * (nxi + 1) + j + 1]) * P.cp + harmonic(props_[p + 1].kn, P.kn) * g.dz / g.deta[i];
    }
    sum += G * Tp;
  }
  return std::numeric_limits<double>::epsilon() * sum / residual_scale(in);
}

int FilmOperator::low_rank_jacobian(double t, const double* y, std::vector<double>& U, std::vector<double>& V) {
  if (!cavity_) return 0;
  // Linearisation of the exchange: a top cell's surface temperature T_s moves its ring's
  // emissive power E_k (V: dE_k / dT_top), the irradiation of every surface follows
  // dH = G dE_rings with the walls in equilibrium (dE_w = b_w dH_w, so
  // G = (I - M_w B_w)^-1 M_rings), and a top cell's residual moves with its ring's H (U).
  const long n = size();
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  update_cavity(y, in);
  const Cavity& c = *cavity_;
  const int nz = grid_.nz, nxi = grid_.nxi, nr = c.rings, ns = c.n;
  const double eps = model_.material.epsilon, sg = kStefanBoltzmann;
  // A = I - M_w B_w over all surfaces (only wall columns of M), then G = A^-1 M_rings.
  std::vector<double> A(static_cast<std::size_t>(ns) * ns, 0.0);
  for (int k = 0; k < ns; ++k) {
    A[static_cast<std::size_t>(k) * ns + k] = 1.0;
    for (int w = nr; w < ns; ++w) {
      const double Tw = c.T_wall[w - nr], ew = c.eps[w];
      const double b = 4 * sg * Tw * Tw * Tw * ew / (4 * ew * sg * Tw * Tw * Tw + c.h + c.wall_U[w - nr]);
      A[static_cast<std::size_t>(k) * ns + w] -= c.M[static_cast<std::size_t>(k) * ns + w] * b;
    }
  }
  const std::vector<double> Ainv = dense_inverse(std::move(A), ns);
  std::vector<double> G(static_cast<std::size_t>(ns) * nr, 0.0);  // row-major ns x nr
  for (int k = 0; k < ns; ++k)
    for (int l = 0; l < ns; ++l) {
      const double a = Ainv[static_cast<std::size_t>(k) * ns + l];
      if (a == 0.0) continue;
      for (int j = 0; j < nr; ++j) G[static_cast<std::size_t>(k) * nr + j] += a * c.M[static_cast<std::size_t>(l) * ns + j];
    }
  U.assign(static_cast<std::size_t>(n) * nr, 0.0);
  V.assign(static_cast<std::size_t>(n) * nr, 0.0);
  for (int i = 0; i < nz; ++i) {
    const int top = i * nxi + nxi - 1, k = c.ring_of[i];
    if (two_flux()) {
      // The ring's emission moves with every zone cell's (and the cell below's) emissive power,
      // and every one of those cells absorbs a share of the ring's irradiation.
      const TwoFluxColumn& col = top_[i];
      const int members = c.ring_begin[k + 1] - c.ring_begin[k], ns = col.n + 2, base = i * nxi;
      auto add = [&](int p, double leaving, double absorbs_H) {
        const double Tp = y[p];
        V[static_cast<std::size_t>(k) * n + p] += leaving * 4 * sg * Tp * Tp * Tp / (c.eps[k] * members);
        const double scale = absorbs_H * grid_.dz / props_[p].capacity;
        for (int j = 0; j < nr; ++j) U[static_cast<std::size_t>(j) * n + p] += scale * G[static_cast<std::size_t>(k) * nr + j];
      };
      for (int q = 0; q < col.n; ++q)
        add(base + top_begin_[i] + q, col.leaving[q], col.absorbed[static_cast<std::size_t>(q) * ns + col.n + 1]);
      add(base + top_below(i), col.leaving[col.n], col.below[col.n + 1]);
      continue;
    }
    const SurfaceState st = surface(i, y[top], props_[top].kn, in);
    const double Ts = st.T_s, rad = 4 * eps * sg * Ts * Ts * Ts;
    double dTs_dTp = 1.0, dflux_dH = eps;
    if (!grid_.lumped) {
      const double kk = 2.0 * props_[top].kn / grid_.deta[i], den = kk + rad + c.h;
      dTs_dTp = kk / den;
      dflux_dH = kk * eps / den;
    }
    const int members = c.ring_begin[k + 1] - c.ring_begin[k];
    V[static_cast<std::size_t>(k) * n + top] = 4 * sg * Ts * Ts * Ts * dTs_dTp / members;
    const double scale = dflux_dH * grid_.dz / props_[top].capacity;
    for (int j = 0; j < nr; ++j) U[static_cast<std::size_t>(j) * n + top] = scale * G[static_cast<std::size_t>(k) * nr + j];
  }
  return nr;
}

double FilmOperator::time_scale() const {
  // Residence time = hold-up / mass flux, or for a resting film the conduction time
  // across it at the inlet state.
  double holdup = 0.0;
  for (int p = 0; p < size(); ++p) holdup += model_.material.rho_s * grid_.phi[p] * grid_.volume(p / grid_.nxi);
  if (grid_.mass_flux > 0.0) return holdup / grid_.mass_flux;
  const CellProps c = props(0, model_.T_in);
  const double t = grid_.tc[0];
  return model_.material.rho_s * grid_.phi[0] * c.cp * t * t / c.kn;
}

}  // namespace centrec::thermal
