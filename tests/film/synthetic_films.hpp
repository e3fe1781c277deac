#pragma once
// Synthetic particle films of known geometry for the sampler tests: layered lattices and
// random packings in an annulus R - t <= r <= R, and a holder for
// structure-of-arrays snapshots.
#include <cstdint>
#include <random>
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/film_sections.hpp"
#include "dem/film/particle_arrays.hpp"

namespace centrec::film::test {

// The default theta convention (gravity along -y, clockwise rotation seen from +z:
// theta = atan2(y, x)) for a drum of radius R and length L.
DrumFrame paper_view_frame(double R, double L);

// Film-section grid over the whole drum with a fixed particle diameter d.
FilmSectionGrid section_grid(int axial_sections, int tangential_bins, double d);

struct Particles : ParticleColumns {
  void add(double px, double py, double pz, double r);
};

// Layers of spheres (diameter d) at centre wall distances d/2 + k h, k = 0..layers-1,
// each a ring lattice of the same angular count (chord >= a_theta on the innermost ring,
// so outer rings are slightly sparser) and axial spacing
// a_z over [0, length); odd layers shifted by half a spacing in theta and z when
// `stagger` is set. Returns the particles; the film's true thickness is
// d/2 + (layers - 1) h + d/2.
Particles layered_lattice(double R, double length, double d, int layers, double h, double a_theta, double a_z,
                          bool stagger);

// A random (fluid-like) packing of spheres of diameter d at solid fraction phi in the
// annulus of thickness t (periodic in z over [0, length)): random centres, then overlap
// relaxation (overlapping pairs pushed 1e-4 d past contact, centres held between the
// walls) until a full pass finds no overlap. Throws std::runtime_error if it never does.
Particles random_packing(double R, double t, double length, double d, double phi, std::mt19937_64& rng);

// Smallest centre distance minus the sum of radii over all pairs (negative = overlap),
// with z periodic over `length`.
double min_gap(const Particles& p, double length);

}  // namespace centrec::film::test
