// Receiver totals, output fields and effective conductivity of the film operator
// (docs/thermal_model.md outputs). The boundary powers are summed from the boundary faces
// only, independently of the cell residuals, so the balance residual tests conservation.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "film_operator.hpp"
#include "physical_constants.hpp"

namespace centrec::thermal {

namespace {
double largest_magnitude(std::initializer_list<double> xs) {
  double m = 0.0;
  for (double x : xs) m = std::max(m, std::fabs(x));
  return m;
}
}  // namespace

double receiver_balance_scale(const FilmBalance& b) {
  return largest_magnitude({b.aperture_power, b.spillage_loss, b.reflected_loss, b.emitted_loss, b.convected,
                            b.walls_convected, b.wall, b.walls_insulation, b.carried, b.inlet_conduction, b.storage});
}

double film_balance_scale(const FilmBalance& b) {
  return largest_magnitude({b.absorbed, b.emitted, b.convected, b.wall, b.carried, b.inlet_conduction, b.storage});
}

double FilmOperator::stored_enthalpy(const double* y) const {
  const double h_in = model_.heat.enthalpy(model_.T_in);
  double H = 0.0;
  for (long p = 0; p < size(); ++p)
    H += model_.material.rho_s * grid_.phi[p] * grid_.volume(static_cast<int>(p) / grid_.nxi) *
         (model_.heat.enthalpy(y[p]) - h_in);
  return H * grid_.perimeter;
}

FilmBalance FilmOperator::balance(double t, const double* y) {
  const FilmGrid& g = grid_;
  const int nxi = g.nxi, nz = g.nz;
  const long n = size();
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  const Inputs in = inputs_at(t);
  if (cavity_) update_cavity(y, in);
  FilmBalance b;
  for (int i = 0; i < nz; ++i) {
    const int top = i * nxi + nxi - 1, bottom = i * nxi;
    const SurfaceState st = surface(i, y[top], props_[top].kn, in);
    const double q = q_column_[i] * in.flux_factor;
    b.incident += q * g.dz;
    b.absorbed += model_.material.alpha * solar_irradiation(i, in) * g.dz;  // at the surface or in the top layers
    b.emitted += (two_flux() ? top_net_emitted(i, y, top_irradiation(i)) : st.emitted) * g.dz;
    b.convected += st.convected * g.dz;
    b.wall += wall_loss(i, y[bottom], props_[bottom].kn) * g.dz;
  }
  const FaceStream out = face_stream(nz, y, in.flow_factor);
  const double m_out = out.mass, H_out = out.enthalpy;
  double H_in = 0.0;
  for (int j = 0; j < nxi; ++j) {
    H_in += in.flow_factor * g.m_axial[j] * model_.heat.enthalpy(model_.T_in);
    b.inlet_conduction += props_[j].kz * (g.tf[0] / nxi) * (y[j] - model_.T_in) / (0.5 * g.dz);
  }
  b.carried = H_out - H_in;
  for (long p = 0; p < n; ++p) b.storage += cell_residual(static_cast<int>(p), y, props_.data(), in);
  b.residual = b.absorbed - b.emitted - b.convected - b.wall - b.carried - b.inlet_conduction;
  // Per unit width -> whole circumference.
  for (double* x : {&b.incident, &b.absorbed, &b.emitted, &b.convected, &b.wall, &b.carried,
                    &b.inlet_conduction, &b.storage, &b.residual})
    *x *= g.perimeter;
  b.mass_flow = m_out * g.perimeter;
  // A resting film has no outlet stream: report the inlet temperature.
  b.T_out = mixing_cup_temperature(out);
  // The case's aperture power: what entered plus what spilled onto the front plate.
  b.aperture_power = cavity_ && model_.cavity.spillage > 0 ? b.incident / (1.0 - model_.cavity.spillage) : b.incident;
  b.spillage_loss = b.aperture_power - b.incident;
  if (cavity_) {
    // Through the aperture: the solar band (linear in the flux factor) and the thermal band
    // from the emissive powers the irradiation was computed from; the walls' losses at
    // their temperatures. Independent of the film's cell residuals.
    const Cavity& c = *cavity_;
    b.reflected_loss = c.solar_out * in.flux_factor;
    std::vector<double> emitted(c.n);
    for (int k = 0; k < c.n; ++k) emitted[k] = c.eps[k] * c.E[k];
    const BandSolution th = c.thermal->solve(emitted, std::vector<double>(c.n, 0.0),
                                             kStefanBoltzmann * std::pow(model_.surface.T_env, 4));
    b.emitted_loss = th.aperture_out - th.aperture_in;
    for (int k = c.rings; k < c.n; ++k) {
      const double Tw = c.T_wall[k - c.rings];
      b.walls_convected += c.h * (Tw - model_.surface.T_air) * c.area[k];
      b.walls_insulation += c.wall_U[k - c.rings] * (Tw - model_.wall.T_amb) * c.area[k];
    }
    b.h_cavity = c.h;
    b.h_natural = c.convection.h_natural;
    b.h_wind = c.convection.h_wind;
    b.h_rotation = c.convection.h_rotation;
    b.grashof = c.convection.Gr;
    b.reynolds_wind = c.convection.Re_wind;
    b.reynolds_rotation = c.convection.Re_rotation;
  } else {
    b.reflected_loss = (1.0 - model_.material.alpha) * b.incident;
    b.emitted_loss = b.emitted;
    b.h_cavity = model_.surface.h_conv;
  }
  b.receiver_residual = b.aperture_power - b.spillage_loss - b.reflected_loss - b.emitted_loss - b.convected - b.walls_convected - b.wall -
                        b.walls_insulation - b.carried - b.inlet_conduction - b.storage;
  b.efficiency = b.aperture_power > kBalanceTolerance * receiver_balance_scale(b)
                     ? b.carried / b.aperture_power
                     : std::numeric_limits<double>::quiet_NaN();
  return b;
}

FilmOperator::FaceStream FilmOperator::face_stream(int f, const double* y, double flow_factor) const {
  const FilmGrid& g = grid_;
  const int nxi = g.nxi;
  FaceStream s;
  for (int j = 0; j < nxi; ++j) {
    const double m = flow_factor * g.m_axial[f * nxi + j];
    const double h = advection_ == Advection::upwind ? props_[(f - 1) * nxi + j].h
                                                     : model_.heat.enthalpy(face_temperature(f, j, y));
    s.mass += m;
    s.enthalpy += m * h;
  }
  return s;
}

double FilmOperator::mixing_cup_temperature(const FaceStream& s) const {
  return s.mass > 0 ? model_.heat.temperature(s.enthalpy / s.mass) : model_.T_in;
}

ThermalFields FilmOperator::fields(double t, const double* y) {
  const FilmGrid& g = grid_;
  const long n = size();
  const Inputs in = inputs_at(t);
  for (long p = 0; p < n; ++p) props_[p] = props(static_cast<int>(p), y[p]);
  if (cavity_) update_cavity(y, in);
  ThermalFields f;
  f.T.assign(y, y + n);
  f.k_n.resize(n);
  f.k_bed.resize(n);
  f.k_rad.resize(n);
  f.k_mix.resize(n);
  for (long p = 0; p < n; ++p) {
    const int c = static_cast<int>(p);
    f.k_bed[p] = k_bed(c, y[p]);
    f.k_rad[p] = model_.conductivity.k_constant > 0 || in_top_zone(c) ? 0.0 : model_.bed.evaluate(y[p], g.phi[p]).k_rad;
    f.k_mix[p] = k_mix(c, y[p]);
    f.k_n[p] = props(c, y[p]).kn;
  }
  for (int i = 0; i < g.nz; ++i) {
    const int top = i * g.nxi + g.nxi - 1, bottom = i * g.nxi;
    const SurfaceState st = surface(i, y[top], f.k_n[top], in);
    f.T_surface.push_back(st.T_s);
    f.q_absorbed.push_back(model_.material.alpha * solar_irradiation(i, in));
    f.q_emitted.push_back(two_flux() ? top_net_emitted(i, y, top_irradiation(i)) : st.emitted);
    f.q_convected.push_back(st.convected);
    f.q_wall.push_back(wall_loss(i, y[bottom], f.k_n[bottom]));
    const FaceStream leaving = face_stream(i + 1, y, in.flow_factor);
    f.T_mixing_cup.push_back(mixing_cup_temperature(leaving));
  }
  if (cavity_) {
    const Cavity& c = *cavity_;
    for (int k = 0; k < c.n; ++k) {
      double T = 0.0;
      if (k < c.rings) {
        const int b = c.ring_begin[k], e = c.ring_begin[k + 1];
        for (int i = b; i < e; ++i) T += f.T_surface[i] / (e - b);
      } else {
        T = c.T_wall[k - c.rings];
      }
      f.cavity_T.push_back(T);
      f.cavity_solar_irradiation.push_back((c.primary[k] + c.H_solar[k]) * in.flux_factor);
      f.cavity_thermal_irradiation.push_back(c.H[k]);
    }
  }
  return f;
}

std::vector<KeffSection> FilmOperator::keff_sections(const double* y) const {
  const FilmGrid& g = grid_;
  BedConductivityModel no_rad = model_.bed;
  no_rad.radiation = false;
  std::vector<KeffSection> out;
  for (int i = 0; i < g.nz; ++i) {
    double u_max = 0.0;
    for (int j = 0; j < g.nxi; ++j) u_max = std::max(u_max, g.u[g.index(i, j)]);
    double thick = 0.0, r_n = 0.0, r_bed = 0.0, r_bed0 = 0.0;
    for (int j = 0; j < g.nxi; ++j) {
      const int p = g.index(i, j);
      if (!(g.u[p] > 1e-9 * u_max)) continue;  // the resting layer is not part of the moving film
      const double kb = k_bed(p, y[p]);
      // The two-flux zone's k_bed has no radiation part (its radiation is not a conductivity).
      const double kb0 = model_.conductivity.k_constant > 0 || in_top_zone(p) ? kb : no_rad.k_bed(y[p], g.phi[p]);
      const double kn = model_.conductivity.mixing ? kb + k_mix(p, y[p]) : kb;
      thick += g.deta[i];
      r_n += g.deta[i] / kn;
      r_bed += g.deta[i] / kb;
      r_bed0 += g.deta[i] / kb0;
    }
    KeffSection s;
    s.z = g.zc[i];
    s.moving_thickness = thick;
    if (thick > 0) {
      s.k_eff = thick / r_n;
      s.bed_conduction = thick / r_bed0;
      s.radiation = thick / r_bed - s.bed_conduction;
      s.mixing = s.k_eff - thick / r_bed;
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace centrec::thermal
