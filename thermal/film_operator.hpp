#pragma once
// The film energy equation discretised by finite volumes on the film grid (docs/thermal_model.md), exposed as an OdeSystem (right-hand side and Jacobian; the integrator is
// separate, docs/architecture.md). Unknown: T per cell, index i * nxi + j (z-major, so the
// Jacobian is banded with half-width nxi, or 2 nxi below the diagonal for the limited
// advection scheme).
//
// Per cell (per unit width):  rho_s phi c_p(T) V dT/dt = sum of face fluxes + sources
//   axial faces:  enthalpy m h(T_face) (upwind, or van Leer-limited MUSCL), conduction k_z
//   xi faces:     enthalpy of the continuity flux (upwind), conduction k_n (harmonic mean)
//   surface:      alpha q - eps sigma F (T_s^4 - T_env^4) - h (T_s - T_air), with T_s from
//                 the local balance against the half-cell conduction (second order)
//   wall:         (T_P - T_amb) / (1/U_w + deta/(2 k)), or adiabatic
//   inlet:        enthalpy m h(T_in) and conduction from T_in at the face; outlet: no
//                 conduction.
// Every face flux is one function of its two sides, so the sum over cells telescopes to
// the boundary powers and the steady energy balance closes to round-off.
#include <algorithm>
#include <memory>
#include <vector>

#include "cavity_convection.hpp"
#include "cavity_radiation.hpp"
#include "film_field.hpp"
#include "film_grid.hpp"
#include "film_model.hpp"
#include "film_top_radiation.hpp"
#include "ode_system.hpp"

namespace centrec::thermal {

// Receiver totals at one instant (W, whole circumference) and the outlet state.
struct FilmBalance {
  double incident = 0.0;     // integral of q over the irradiated film surface
  double absorbed = 0.0;
  double emitted = 0.0;
  double convected = 0.0;
  double wall = 0.0;
  double carried = 0.0;      // enthalpy out at z = L minus enthalpy in at z = 0
  double inlet_conduction = 0.0;  // conducted back out through the inlet face
  double storage = 0.0;      // d/dt of the film's enthalpy
  double residual = 0.0;     // absorbed - emitted - convected - wall - carried - inlet_conduction - storage
  double T_out = 0.0;        // mixing-cup outlet temperature (weight rho_b u c_p), K
  double mass_flow = 0.0;    // kg/s
  double efficiency = 0.0;   // carried / aperture_power; NaN without sunlight to speak of (below)
  // Receiver view (cavity model; the open-surface model fills the same fields with
  // aperture_power = incident, reflected_loss = (1 - alpha) incident, emitted_loss = emitted).
  double aperture_power = 0.0;    // concentrated sunlight entering through the aperture
  double reflected_loss = 0.0;    // sunlight leaving through the aperture
  double emitted_loss = 0.0;      // net thermal radiation leaving through the aperture
  double walls_convected = 0.0;   // back plate and front annulus to the air
  double walls_insulation = 0.0;  // back plate and front annulus through their insulation
  double spillage_loss = 0.0;     // concentrated sunlight on the front plate's outer face, not entering
  double h_cavity = 0.0;          // convection coefficient used, W/(m2 K)
  // Its parts with the cavity correlation (thermal/cavity_convection.hpp; before the error
  // budget's scale), the correlation's Gr_L, the wind's and the rotation's Reynolds numbers.
  double h_natural = 0.0, h_wind = 0.0, h_rotation = 0.0;
  double grashof = 0.0, reynolds_wind = 0.0, reynolds_rotation = 0.0;
  // aperture_power - spillage_loss - reflected_loss - emitted_loss - convected - walls_convected -
  // wall - walls_insulation - carried - inlet_conduction - storage
  double receiver_residual = 0.0;
};

// The solved film's temperature and heat-flow fields for output, per cell [nz * nxi] unless noted.
struct ThermalFields {
  std::vector<double> T, k_n, k_bed, k_rad, k_mix;
  std::vector<double> T_surface, q_absorbed, q_emitted, q_convected, q_wall;  // per column [nz], W/m2
  // Per column [nz]: the mixing-cup temperature of the stream leaving it (weight rho_b u c_p,
  // as T_out, which is the last column's), K.
  std::vector<double> T_mixing_cup;
  // Cavity model: enclosure surfaces (rings, back plate, front annulus), per surface.
  std::vector<double> cavity_T, cavity_solar_irradiation, cavity_thermal_irradiation;  // K, W/m2, W/m2
};

// Effective wall-normal conductivity of the moving film per axial section (docs/thermal_model.md): series value t_m / integral(d eta / k) over the cells with u > 0, and its
// additive parts: k_eff = bed_without_radiation + radiation + mixing.
struct KeffSection {
  double z = 0.0, moving_thickness = 0.0;
  double k_eff = 0.0, bed_conduction = 0.0, radiation = 0.0, mixing = 0.0;
};

// The balances are judged against their largest power: the receiver's (the aperture power,
// or a loss or the carried power where the sunlight is weak) and the film's (absorbed,
// emitted, convected, wall, carried, inlet conduction, storage), W. A residual above
// kBalanceTolerance of it is a defect, not a result; an aperture power below that fraction
// of it leaves the efficiency undefined (NaN).
constexpr double kBalanceTolerance = 1e-6;
double receiver_balance_scale(const FilmBalance& b);
double film_balance_scale(const FilmBalance& b);

class FilmOperator : public OdeSystem {
 public:
  FilmOperator(const FilmField& film, const FilmModel& model, const FilmGridSpec& spec);

  long size() const override { return static_cast<long>(grid_.nz) * grid_.nxi; }
  long lower_bandwidth() const override;
  long upper_bandwidth() const override { return grid_.nxi; }
  bool rhs(double t, const double* y, double* ydot) override;
  bool jacobian(double t, const double* y, const double* fy, const BandEntrySink& sink) override;
  double steady_residual(double t, const double* y) override;
  double steady_residual_floor(double t, const double* y) override;
  double time_scale() const override;
  // Cavity model: the radiation exchange between rings, U V^T with one column per ring.
  int low_rank_jacobian(double t, const double* y, std::vector<double>& U, std::vector<double>& V) override;

  // When frozen, the flux and flow time factors are taken at t = 0 whatever t is given
  // (a steady state for the initial operating point).
  void freeze_inputs(bool frozen) { frozen_ = frozen; }
  // Replace a time history between integrations (the outlet controller sets the mass flow
  // per control interval, thermal/outlet_controller.hpp). Only inputs_at reads them, so
  // nothing else changes; an integrator over this operator must be reinitialised at the
  // time of the change. Throws std::invalid_argument for a bad factor (TimeFactor::check).
  void set_flux_time(const TimeFactor& f) {
    f.check();
    model_.flux_time = f;
  }
  void set_flow_time(const TimeFactor& f) {
    f.check();
    model_.flow_time = f;
  }

  FilmBalance balance(double t, const double* y);
  ThermalFields fields(double t, const double* y);
  // The film's enthalpy above the inlet state, sum of rho_s phi V (h(T) - h(T_in)) over the
  // cells, whole circumference (J): what a change of the film's geometry at fixed cell
  // temperatures creates or destroys (thermal/outlet_controller.hpp).
  double stored_enthalpy(const double* y) const;
  std::vector<KeffSection> keff_sections(const double* y) const;

  const FilmGrid& grid() const { return grid_; }
  // Irradiated film surface pi D_f L (m2) and the cavity's aperture disc (m2; 0 for the
  // open surface): the two planes a solar flux can be quoted at (docs/cavity_model.md).
  double film_area() const;
  double aperture_area() const;
  bool cavity() const { return cavity_ != nullptr; }
  // Cavity model: the axial position of each enclosure surface, in the order of the
  // per-surface outputs (cavity_T, ...): the rings' centres, the back plate at 0, the front
  // annulus (if any) at the film's length L. Empty without a cavity.
  std::vector<double> cavity_surface_z() const;
  const FilmModel& model() const { return model_; }
  std::vector<double> uniform_state(double T) const { return std::vector<double>(size(), T); }

 private:
  struct CellProps {
    double cp = 0, h = 0, kn = 0, kz = 0, capacity = 0;  // capacity = rho_s phi c_p V
  };
  struct Inputs {
    double flux_factor = 1.0, flow_factor = 1.0, t = 0.0;
  };
  struct SurfaceState {
    double T_s = 0, absorbed = 0, emitted = 0, convected = 0;
  };
  Inputs inputs_at(double t) const;
  CellProps props(int p, double T) const;
  double k_bed(int p, double T) const;  // ZBS (or the constant override) at the cell's phi
  double k_mix(int p, double T) const;  // phi rho_s c_p D
  // Temperature advected through axial face f (0..nz) of stripe j.
  double face_temperature(int f, int j, const double* T) const;
  // The stream through axial face f (1..nz) over the column: its mass flow per width and the
  // enthalpy it carries (props_ must hold the props of T).
  struct FaceStream {
    double mass = 0.0, enthalpy = 0.0;  // kg/(m s), W/m
  };
  FaceStream face_stream(int f, const double* T, double flow_factor) const;
  // Its mixing-cup temperature (T_in for a stream at rest).
  double mixing_cup_temperature(const FaceStream& s) const;
  SurfaceState surface(int i, double T_p, double kn, const Inputs& in) const;
  double solar_irradiation(int i, const Inputs& in) const;    // primary + diffuse sunlight on column i, W/m2
  // Cavity model: brings the enclosure state (surface temperatures of the columns and
  // walls, thermal irradiation, convection coefficient) to a fixed point for the film
  // state T; props_ must hold the props of T. The band Jacobian sees the irradiation as
  // given (the nonlocal coupling is left to the Newton iterations).
  void update_cavity(const double* T, const Inputs& in);
  void setup_cavity();
  double wall_loss(int i, double T_p, double kn) const;       // W/m2 out of the film
  double absorbed_share(int i, int j) const;                  // fraction of alpha q absorbed in cell
  // Two-flux film top (thermal/film_top_radiation.hpp): the zone's first cell in column i, the
  // cell below it that the zone's lower boundary belongs to, the irradiation from above, the
  // thermal power absorbed in cell j (zone or the cell below; W/m2), the net thermal emission
  // leaving the top (W/m2) and its part independent of H.
  bool two_flux() const { return !top_.empty(); }
  bool in_top_zone(int p) const { return two_flux() && p % grid_.nxi >= top_begin_[p / grid_.nxi]; }
  int top_below(int i) const { return std::max(top_begin_[i] - 1, 0); }
  double top_irradiation(int i) const;
  double top_absorbed(int i, int j, const double* T, double H) const;
  double top_net_emitted(int i, const double* T, double H) const;
  double top_escaping(int i, const double* T) const;
  void setup_film_top();
  bool volumetric() const {
    return model_.surface.absorb_depth_layers > 0 || model_.surface.extinction_depth_d != 0;
  }
  double cell_residual(int p, const double* T, const CellProps* pr, const Inputs& in) const;
  double residual_scale(const Inputs& in) const;  // the power steady_residual is divided by, W/m

  FilmGrid grid_;
  FilmModel model_;
  Advection advection_;
  bool frozen_ = false;
  std::vector<double> q_column_;      // q(z_i), W/m2
  std::vector<CellProps> props_;      // scratch: props at the current state
  std::vector<double> jac_scratch_;
  std::vector<double> extinction_depth_;  // per column, m (exponential solar absorption)
  std::vector<double> local_share_;       // per cell: absorbed share from the local phi (extinction_local)
  std::vector<TwoFluxColumn> top_;        // per column: the two-flux zone's response (film_top.two_flux)
  std::vector<int> top_begin_;            // per column: first cell of the zone

  struct Cavity {
    std::unique_ptr<CavityEnclosure> solar;  // reflectances 1 - alpha
    std::unique_ptr<CavityEnclosure> thermal;  // reflectances 1 - eps
    double solar_out = 0.0;                  // sunlight leaving through the aperture at flux factor 1, W
    std::vector<double> eps;                 // thermal emissivity per surface
    std::vector<double> wall_alpha, wall_U;  // per wall (back plate, front plate): solar absorptance, insulation W/(m2 K)
    std::vector<double> M, m;                // thermal irradiation H = M E + m E_env
    std::vector<double> H_solar;             // diffuse solar irradiation at flux factor 1, W/m2
    std::vector<double> primary;             // primary solar per surface at flux factor 1, W/m2
    std::vector<int> ring_of;                // ring of each column
    std::vector<int> ring_begin;             // first column of each ring [rings + 1]
    std::vector<double> area;                // per surface, m2
    int rings = 0, n = 0;                    // rings, non-aperture surfaces
    // State of the last update.
    std::vector<double> H, T_s, T_wall, E;   // irradiation per surface, column T_s, wall T, emissive power
    double h = 0.0;
    CavityConvection convection;             // the correlation's parts (when it is used)
  };
  std::unique_ptr<Cavity> cavity_;
};

}  // namespace centrec::thermal
