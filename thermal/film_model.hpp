#pragma once
// Everything the film energy equation needs besides the film field and the grid
// (docs/thermal_model.md): material, conductivity model, solar flux and its time history,
// surface / wall / inlet conditions. Plain structs with the design defaults; the YAML
// reader at the program's edge fills them.
#include <functional>

#include "bed_conductivity.hpp"
#include "flux_profile.hpp"
#include "heat_capacity.hpp"
#include "material.hpp"
#include "time_factor.hpp"

namespace centrec::thermal {

// Surface eta = t, facing the cavity. Open-surface model: absorbed alpha q, emitted
// eps sigma F (T^4 - T_env^4), convected h (T - T_air). Cavity model (CavitySettings): the
// solar and thermal irradiation come from the enclosure, the convection coefficient from
// the cavity correlation (or h_conv), T_env is the surroundings seen through the aperture
// and T_air the ambient air.
struct SurfaceConditions {
  double loss_factor = 1.0;        // F (open surface only), 1 = open surface, < 1 = the cavity returns radiation
  double T_env = 300.0;            // radiative environment, K
  double h_conv = 0.0;             // W/(m2 K)
  double T_air = 300.0;            // K
  double absorb_depth_layers = 0;  // > 0: solar absorbed uniformly over n particle diameters
  // > 0: solar absorbed with exp(-depth / (n d)) below the surface (Beer-Lambert); < 0: n from
  // the column's mean solid fraction, n = (1 - phi) / (1.5 phi) (the volume-scattering
  // extinction coefficient of a bed of large opaque spheres, beta = 1.5 phi / ((1 - phi) d),
  // Brewster 2004, J. Heat Transfer 126, 1048). 0 and absorb_depth_layers 0: at the surface.
  double extinction_depth_d = 0;
  // Multiplies the extinction depth, given or from phi (the error budget's perturbation;
  // 1 changes no arithmetic).
  double extinction_scale = 1.0;
  // With the depth from phi (extinction_depth_d < 0): each cell's own phi instead of the
  // column mean (thermal/solar_extinction.hpp).
  bool extinction_local = false;
};

// The drum interior as a diffuse grey enclosure (thermal/cavity_view_factors.hpp,
// cavity_radiation.hpp): film rings, back plate, front annulus, aperture at z = L.
struct CavitySettings {
  bool enabled = false;              // false: the open-surface model with loss factor F
  double aperture_diameter = 0.0;    // m; 0 = the drum diameter (open front end, no annulus)
  int rings = 25;                    // axial film sections of the enclosure (columns grouped)
  double wall_absorptance = 0.3;     // solar absorptance of the back plate and front annulus
  double wall_emissivity = 0.8;      // their thermal emissivity
  bool convection_correlation = true;  // Siebers & Kraabel / Stine & McDonald; false: surface.h_conv
  double convection_scale = 1.0;       // multiplies the correlation's h (the error budget's perturbation)
  double tilt_rad = 0.7853981633974483;  // cavity axis below the horizontal (aperture facing down)
};

// Wall eta = 0: loss through the insulation U_w (T_wall - T_amb), or adiabatic.
struct WallConditions {
  bool adiabatic = false;
  double U_w = 1.0;      // W/(m2 K)
  double T_amb = 300.0;  // K
};

struct ConductivitySettings {
  double k_constant = 0.0;       // W/(m K); > 0 replaces the ZBS bed model (analytic tests)
  bool mixing = true;            // add k_mix = phi rho_s c_p D to the wall-normal conductivity
  enum class Axial { bed, bed_and_mixing, none };
  Axial axial = Axial::bed;      // k_z: bed only (default), bed + mixing (isotropic D), or none
};

struct FilmModel {
  Material material;
  BedConductivityModel bed;  // shape factor, flattening; k_s, epsilon, d are synced from material
  HeatCapacity heat;
  ConductivitySettings conductivity;
  FluxProfile flux;
  TimeFactor flux_time;       // q(z, t) = flux(z) * flux_time(t)
  TimeFactor flow_time;       // u(z, eta, t) = u(z, eta) * flow_time(t) (mass-flow change)
  SurfaceConditions surface;
  CavitySettings cavity;
  WallConditions wall;
  double T_in = 300.0;        // inlet temperature, K
  // Optional volumetric heat source (W/m3) at (z, eta, t): manufactured-solution tests.
  std::function<double(double z, double eta, double t)> source;
};

enum class Advection { upwind, van_leer };

struct FilmGridSpec {
  int nz = 200;     // axial cells
  int nxi = 40;     // wall-normal cells (xi = eta / t); forced to 1 when lumped
  bool lumped = false;  // 1D depth-lumped variant: T(z) only, surface and wall at the film T
  // van Leer by default: at 200 x 40 the first-order upwind scheme moves the outlet
  // temperature of an open film by up to 0.8 K from the converged value, van Leer by a tenth
  // of that where advection dominates the error (docs/thermal_model.md, "Discretisation").
  Advection advection = Advection::van_leer;
};

}  // namespace centrec::thermal
