#pragma once
// Natural-convection loss of an open cavity receiver (docs/cavity_model.md): the correlation
// of Siebers & Kraabel (1984, "Estimating convective energy losses from solar central
// receivers", Sandia SAND84-8717) with the inclination and aperture factor of Stine &
// McDonald (1989, "Cavity receiver convective heat loss", Proc. ISES Solar World Congress),
// as reviewed by Samanes, Garcia-Barberena & Zaversky (2015, Energy Procedia 69, 543-552):
//     Nu_L = 0.088 Gr_L^(1/3) (T_w / T_inf)^0.18 (cos theta)^2.47 (d_ap / L)^s,
//     s = 1.12 - 0.982 d_ap / L,   h = Nu_L k_air / L,
// Gr_L = g (T_w - T_inf) L^3 / (T_inf nu^2) with air properties at T_inf, L the cavity's
// internal diameter, theta the tilt of the cavity axis below the horizontal (0: aperture
// facing sideways, 90 deg: facing down, no convective loss) and T_w the area-weighted mean
// temperature of the cavity surfaces. h applies to every cavity surface.

namespace centrec::thermal {

// Kinematic viscosity of air at 1 atm, m2/s: Sutherland's law for mu (mu_0 = 1.716e-5 Pa s at
// 273.15 K, S = 110.4 K) over the ideal-gas density.
double air_kinematic_viscosity(double T_kelvin);

// W/(m2 K); 0 if T_wall <= T_inf or the aperture faces straight down.
double cavity_convection_coefficient(double T_wall_mean, double T_inf, double cavity_diameter, double aperture_diameter,
                                     double tilt_rad);

}  // namespace centrec::thermal
