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
  // With the depth from phi (extinction_depth_d < 0): each cell's own phi (thermal/
  // solar_extinction.hpp), or the column mean (false; it lays sunlight into a loose top by
  // depth alone, docs/slice_vs_drum_thermal.md).
  bool extinction_local = true;
};

// Sunlight absorbed by each cell's own solid fraction (Beer-Lambert from the local phi): the
// one rule the two-flux film top agrees with (its cells absorb and emit by their own phi).
inline bool solar_by_local_phi(const SurfaceConditions& s) {
  return s.absorb_depth_layers == 0.0 && s.extinction_depth_d < 0.0 && s.extinction_local;
}

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
  // Mixed convection with the correlation (thermal/cavity_convection.hpp): wind (Ma 1993) and
  // the drum's rotation (Seghir-Ouali et al. 2006) mixed with the natural part by
  // (sum h^n)^(1/n). Both 0: natural convection alone, h exactly the natural correlation's.
  double wind_speed = 0.0;             // m/s, at the aperture
  double rotation_rad_s = 0.0;         // drum angular speed for the rotation-driven part
  double mixing_exponent = 3.2;        // n of the mixing rule (Siebers & Kraabel)
  // Spillage: the share of the concentrated power at the aperture plane (the case's flux,
  // docs/cavity_model.md "Spillage") that lands on the front plate's outer face instead of
  // entering; it is lost to the ambient outside the cavity. The film gets (1 - spillage) of
  // the case's flux; the efficiency stays carried / the case's aperture power.
  double spillage = 0.0;
  double tilt_rad = 0.7853981633974483;  // cavity axis below the horizontal (aperture facing down)
  // Front plate: the annulus aperture..drum radius at z = L (docs/cavity_model.md, "Front
  // plate"), a grey diffuse wall in the enclosure that loses plate_U (T - T_amb) through its
  // insulation and convects to the cavity air like the other walls (0: adiabatic, a
  // reradiating surface). A value < 0 takes the drum wall's U_w and the back plate's
  // wall_absorptance / wall_emissivity.
  double plate_U = -1.0;             // W/(m2 K)
  double plate_absorptance = -1.0;   // solar
  double plate_emissivity = -1.0;    // thermal
};

// Wall eta = 0: loss through the insulation U_w (T_wall - T_amb), or adiabatic.
struct WallConditions {
  bool adiabatic = false;
  double U_w = 1.0;      // W/(m2 K)
  double T_amb = 300.0;  // K
};

// The thermal band in the film's top (docs/thermal_model.md, "The film top as a participating
// medium"). surface: the top cell emits as a grey surface at the surface temperature and the
// bed conductivity carries the radiation between particles (ZBS's k_rad) everywhere.
// two_flux: the cells within depth_d particle diameters of the surface form a participating
// medium (thermal/film_top_radiation.hpp) that emits and absorbs per cell and exchanges with
// the cavity through its top; there the bed conductivity drops k_rad, and below ZBS's range
// (phi < zbs_min_phi) it is Maxwell's conduction of dispersed spheres.
struct FilmTopRadiation {
  bool two_flux = false;
  double depth_d = 3.0;        // particle diameters below the surface
  double zbs_min_phi = 0.4;    // ZBS's lower validity (packed beds, porosity <= 0.6)
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
  FilmTopRadiation film_top;
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
