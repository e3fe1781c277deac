#include "film_operator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physical_constants.hpp"

namespace centrec::thermal {

namespace {
// van Leer limited slope from the backward (a) and forward (b) differences: second order
// where smooth, zero at extrema, so the face value stays between its neighbours.
double van_leer(double a, double b) { return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; }
double harmonic(double a, double b) { return 2.0 * a * b / (a + b); }
}  // namespace

FilmOperator::FilmOperator(const FilmField& film, const FilmModel& model, const FilmGridSpec& spec)
    : grid_(build_film_grid(film, spec, model.material.rho_s)), model_(model), advection_(spec.advection) {
  model_.flux.check();
  // The bed model shares the particle parameters with the material (one source of truth).
  model_.bed.k_s = model_.material.k_s;
  model_.bed.epsilon = model_.material.epsilon;
  model_.bed.d = model_.material.d;
  const Material& m = model_.material;
  if (!(m.rho_s > 0 && m.k_s > 0 && m.d > 0)) throw std::invalid_argument("material: rho_s, k_s and d must be > 0");
  if (!(m.alpha >= 0 && m.alpha <= 1 && m.epsilon > 0 && m.epsilon <= 1))
    throw std::invalid_argument("material: alpha must be in [0, 1] and epsilon in (0, 1]");
  if (!(model_.T_in > 0)) throw std::invalid_argument("inlet temperature must be > 0 K");
  q_column_.resize(grid_.nz);
  for (int i = 0; i < grid_.nz; ++i) q_column_[i] = model_.flux.at(grid_.zc[i]);
  props_.resize(size());
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
  return kc > 0 ? kc : model_.bed.k_bed(T, grid_.phi[p]);
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
  const double eps_sigma_F = model_.material.epsilon * kStefanBoltzmann * s.loss_factor;
  SurfaceState st;
  const double Aq = s.absorb_depth_layers > 0 ? 0.0 : model_.material.alpha * q_column_[i] * in.flux_factor;
  st.absorbed = Aq;
  if (grid_.lumped) {
    st.T_s = T_p;
  } else {
    // Local balance kk (T_s - T_p) = Aq - eps sigma F (T_s^4 - T_env^4) - h (T_s - T_air):
    // g(T_s) is increasing and convex, and g >= 0 at the start point, so Newton converges
    // monotonically from above.
    const double kk = 2.0 * kn / grid_.deta[i];
    auto g = [&](double x) {
      return kk * (x - T_p) + eps_sigma_F * (x * x * x * x - std::pow(s.T_env, 4)) + s.h_conv * (x - s.T_air) - Aq;
    };
    double x = std::max({T_p, s.T_env, s.T_air}) + Aq / (kk + s.h_conv);
    for (int it = 0; it < 100; ++it) {
      const double dg = kk + 4.0 * eps_sigma_F * x * x * x + s.h_conv;
      const double dx = g(x) / dg;
      x -= dx;
      if (std::abs(dx) <= 1e-14 * x) break;
    }
    st.T_s = x;
  }
  const double Ts = st.T_s;
  st.emitted = eps_sigma_F * (Ts * Ts * Ts * Ts - std::pow(s.T_env, 4));
  st.convected = s.h_conv * (Ts - s.T_air);
  return st;
}

double FilmOperator::wall_loss(int i, double T_p, double kn) const {
  const auto& w = model_.wall;
  if (w.adiabatic) return 0.0;
  if (grid_.lumped) return w.U_w * (T_p - w.T_amb);
  return (T_p - w.T_amb) / (1.0 / w.U_w + 0.5 * grid_.deta[i] / kn);
}

double FilmOperator::absorbed_share(int i, int j) const {
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
  if (share > 0) R += share * model_.material.alpha * q_column_[i] * in.flux_factor * g.dz;
  if (model_.source) R += model_.source(g.zc[i], g.eta_center(i, j), in.t) * g.volume(i);
  return R;
}

bool FilmOperator::rhs(double t, const double* y, double* ydot) {
  const long n = size();
  for (long p = 0; p < n; ++p)
    if (!(y[p] > 0.0) || !std::isfinite(y[p])) return false;
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
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
  int rows[6];
  for (long l = 0; l < n; ++l) {
    const int i = static_cast<int>(l) / nxi, j = static_cast<int>(l) % nxi;
    int nr = 0;
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

double FilmOperator::steady_residual(double t, const double* y) {
  const long n = size();
  for (long p = 0; p < n; ++p)
    if (!(y[p] > 0.0) || !std::isfinite(y[p])) return INFINITY;
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  double sum = 0.0;
  for (long p = 0; p < n; ++p) sum += std::abs(cell_residual(static_cast<int>(p), y, props_.data(), in));
  // Scale: the absorbed power, or if there is none the power of a 1 K rise of the flow.
  double scale = 0.0;
  for (int i = 0; i < grid_.nz; ++i) scale += model_.material.alpha * q_column_[i] * in.flux_factor * grid_.dz;
  scale = std::max(scale, grid_.mass_flux * in.flow_factor * model_.heat.cp(model_.T_in) * 1.0);
  if (!(scale > 0.0)) {
    // Neither flux nor flow (a resting film with sources): heating the film by 1 K over
    // its conduction time.
    double capacity = 0.0;
    for (long p = 0; p < n; ++p) capacity += props_[p].capacity;
    scale = capacity / time_scale();
  }
  return sum / scale;
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
