#pragma once
// Exact-geometry volume of a sphere inside a coaxial cylinder, and so inside an annular
// shell r_in <= sqrt(x^2 + y^2) < r_out: the solid-fraction sampler's kernel.
//
// Method: cut the sphere into slices normal to the drum axis. Each slice is a disk of
// radius s = sqrt(a^2 - zeta^2) whose centre is a distance c from the axis; its area
// inside the circle of radius rho is the circle-circle lens area, in closed form. The
// slice areas are integrated over zeta on each stretch between the zeta where the lens
// changes form (disk tangent to the circle): in closed form where the slices lie wholly
// inside or outside, else by 12-point Gauss-Legendre after a sine substitution that
// smooths the tangency. Accuracy: better than 1e-6 of the sphere volume
// (tests/film/test_solid_fraction.cpp checks it against the flat-wall cap formula
// and Monte Carlo). Curvature of the wall is kept; nothing assumes D >> d.
namespace centrec::film {

// Area of the disk (radius s, centre at distance c from the origin) inside the circle of
// radius rho about the origin.
double disk_in_circle_area(double rho, double s, double c);

// Volume of the sphere (radius a, centre at distance c from the axis) inside the
// infinite cylinder of radius rho about the axis.
double sphere_in_cylinder_volume(double rho, double a, double c);

// Volume of the sphere inside the shell r_in <= r < r_out.
double sphere_in_shell_volume(double r_in, double r_out, double a, double c);

}  // namespace centrec::film
