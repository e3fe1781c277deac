#pragma once
// Flux nonuniform around the circumference (docs/cavity_model.md, "Flux around the
// circumference"). The film model is axisymmetric (axial position and depth), so a flux map
// that varies with the angle around the drum cannot enter it as a field. The drum turns the
// film through that map once per revolution: a particle at the surface sees the periodic
// flux q(t) = q_mean (1 + a cos(omega t)). What the axisymmetric model misses is the
// response to the periodic part: a surface temperature ripple, and through the nonlinear
// emission a mean loss above sigma T_mean^4. Both are estimated here, as plain functions of
// the film's properties; they are not added to the film equation.

namespace centrec::thermal {

// Amplitude of the surface temperature of a semi-infinite solid (conductivity k, volumetric
// heat capacity rho_c) under a surface flux q_amplitude cos(omega t), after the transient
// (Carslaw & Jaeger 1959, Conduction of Heat in Solids, section 2.6):
// theta = q_amplitude / sqrt(k rho_c omega). With the sunlight absorbed below the surface
// (Beer-Lambert) the ripple is smaller, so this is an upper estimate.
double surface_ripple_amplitude(double q_amplitude, double k, double rho_c, double omega);

// Mean over one period of T^4 - T_mean^4 for T = T_mean + theta cos(phi):
// 3 T_mean^2 theta^2 + (3/8) theta^4 (the odd powers of cos average to zero). Times
// eps sigma, the film's extra emission.
double ripple_t4_excess(double T_mean, double theta);

}  // namespace centrec::thermal
