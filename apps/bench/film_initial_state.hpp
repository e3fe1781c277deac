#pragma once
// The deterministic initial film both engines start from: packed rings of particles on
// the drum wall, rigidly co-rotating with the drum. Written to a plain text file and read
// back, so each engine is fed from the very numbers in that file.
#include <string>
#include <vector>

#include "bench/film_case.hpp"

namespace centrec::bench {

struct ParticleState {
  double x[3], v[3], w[3];  // position m, velocity m/s, angular velocity rad/s
};

struct FilmState {
  double length = 0.0;      // periodic length along z, m: the domain is [0, length)
  double diameter = 0.0;    // m (monodisperse)
  std::vector<ParticleState> particles;
};

// Lattice film of about target_n particles: case.layers rings stacked inwards from the
// wall, each ring holding as many particles as fit at centre distance >= 1.01 d, rows
// 1.01 d apart along z, odd layers shifted half a row so adjacent layers nest (layer
// spacing chosen so no two particles overlap), each centre jittered deterministically by
// up to 0.2 % d per coordinate. Solid fraction about 0.6.
FilmState make_film_lattice(const FilmCase& c, long target_n);

// Particles per axial row of the lattice (to pick N).
long film_particles_per_row(const FilmCase& c);

// Plain text: '#' header lines (length, diameter, count), then one particle per line:
// x y z vx vy vz wx wy wz (SI, %.17g). Throws std::runtime_error on I/O or format errors.
void write_film_state(const std::string& path, const FilmState& s);
FilmState read_film_state(const std::string& path);

}  // namespace centrec::bench
