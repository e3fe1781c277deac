#pragma once
// A read-only, structure-of-arrays view of one particle snapshot in the drum frame,
// so the DEM engine can hand its own arrays to the film samplers without copies.
//
// Drum frame (docs/centrec_scene.md): drum axis = z, inlet (back plate) at z = 0,
// outlet at z = L, wall at sqrt(x^2 + y^2) = R. SI units throughout.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace centrec::film {

struct ParticleArrays {
  std::size_t count = 0;
  const double* x = nullptr;   // m
  const double* y = nullptr;   // m
  const double* z = nullptr;   // m, 0 at the inlet, L at the outlet
  const double* vx = nullptr;  // m/s (may stay null: no sampler reads it)
  const double* vy = nullptr;  // m/s (may stay null: no sampler reads it)
  const double* vz = nullptr;  // m/s, axial velocity, > 0 towards the outlet
  const double* radius = nullptr;     // m
  const std::int64_t* id = nullptr;   // persistent particle id (dispersion only)
  double time = 0.0;                  // s, simulated time of the snapshot
};

// Owning columns for a snapshot (copied out of an engine, or built by a test).
struct ParticleColumns {
  std::vector<double> x, y, z, vx, vy, vz, radius;
  std::vector<std::int64_t> id;
  double time = 0.0;
  std::size_t size() const { return x.size(); }
  ParticleArrays view() const;
};

// Throws std::invalid_argument naming the first of the listed arrays that is null
// while count > 0. `needs` is a string of letters: x y z v(=vz) r(=radius) i(=id).
void require_arrays(const ParticleArrays& p, const char* needs, const char* who);

}  // namespace centrec::film
