#pragma once
// Convective loss of the receiver cavity (docs/cavity_model.md, "Convection").
//
// Natural convection: the correlation of Siebers & Kraabel (1984, "Estimating convective
// energy losses from solar central receivers", Sandia SAND84-8717) with the inclination and
// aperture factor of Stine & McDonald (1989, "Cavity receiver convective heat loss", Proc.
// ISES Solar World Congress), as reviewed by Samanes, Garcia-Barberena & Zaversky (2015,
// Energy Procedia 69, 543-552):
//     Nu_L = 0.088 Gr_L^(1/3) (T_w / T_inf)^0.18 (cos theta)^2.47 (d_ap / L)^s,
//     s = 1.12 - 0.982 d_ap / L,   h = Nu_L k_air / L,
// Gr_L = g (T_w - T_inf) L^3 / (T_inf nu^2) with air properties at T_inf, L the cavity's
// internal diameter, theta the tilt of the cavity axis below the horizontal (0: aperture
// facing sideways, 90 deg: facing down, no convective loss) and T_w the area-weighted mean
// temperature of the cavity surfaces. h applies to every cavity surface.
//
// Wind (forced): Ma (1993, "Wind effects on convective heat loss from a cavity receiver for
// a parabolic concentrating solar collector", Sandia SAND92-7293): h_w = 0.1967 V^1.849
// W/(m2 K), V the wind speed in m/s, over the cavity surface, without a dependence on the
// wind's direction.
//
// Rotation: the film surface turns with the drum and drags the cavity air. Heat transfer
// inside a rotating cylinder without axial through-flow, Seghir-Ouali, Saury, Harmand,
// Phillipart & Laloy (2006, Int. J. Thermal Sciences 45, 1166-1178):
//     Nu_D = 0.01963 Re_a^0.9285 + 8.5101e-6 Re_r^1.4513 (Re_a = 0 here),
//     Re_r = omega D^2 / nu,  h_r = Nu_D k_air / D,
// air properties at the film temperature (T_w + T_inf) / 2.
//
// Combined: h = (h_n^n + h_w^n + h_r^n)^(1/n), the mixing rule Siebers & Kraabel recommend
// for natural and forced convection on receivers with n = 3.2 (n = 1 adds them, Ma's
// practice). With one part alone, h is that part exactly.

namespace centrec::thermal {

// Kinematic viscosity of air at 1 atm, m2/s: Sutherland's law for mu (mu_0 = 1.716e-5 Pa s at
// 273.15 K, S = 110.4 K) over the ideal-gas density.
double air_kinematic_viscosity(double T_kelvin);

// Natural convection. W/(m2 K); 0 if T_wall <= T_inf or the aperture faces straight down.
double cavity_convection_coefficient(double T_wall_mean, double T_inf, double cavity_diameter, double aperture_diameter,
                                     double tilt_rad);
// Gr_L of the natural-convection correlation (0 if T_wall <= T_inf).
double cavity_grashof(double T_wall_mean, double T_inf, double cavity_diameter);

// Ma's wind correlation, W/(m2 K) (0 at V = 0).
double wind_convection_coefficient(double wind_speed);

// Seghir-Ouali et al.'s rotating cylinder without through-flow, W/(m2 K) (0 at omega = 0);
// Re_r = omega D^2 / nu at the film temperature is returned through Re_r if given.
double rotation_convection_coefficient(double omega_rad_s, double diameter, double T_wall_mean, double T_inf,
                                       double* Re_r = nullptr);

// (sum of h_i^n)^(1/n) over the non-zero parts; exactly the part when only one is non-zero.
double mixed_convection(double h_natural, double h_wind, double h_rotation, double n);

struct CavityConvection {
  double h = 0.0, h_natural = 0.0, h_wind = 0.0, h_rotation = 0.0;  // W/(m2 K)
  double Gr = 0.0;           // natural: Gr_L at the cavity diameter
  double Re_wind = 0.0;      // V D_ap / nu(T_inf), for orientation (Ma's correlation is dimensional)
  double Re_rotation = 0.0;  // omega D^2 / nu at the film temperature
};
// The parts and their mix for a cavity of diameter D and aperture d_ap.
CavityConvection cavity_mixed_convection(double T_wall_mean, double T_inf, double cavity_diameter,
                                         double aperture_diameter, double tilt_rad, double wind_speed,
                                         double omega_rad_s, double mixing_exponent);

}  // namespace centrec::thermal
