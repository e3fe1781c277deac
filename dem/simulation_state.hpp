#pragma once
// The engine's full dynamic state, for checkpoints (docs/outputs.md): everything a
// Simulation needs to continue a run as if it had never stopped. Particles are listed in
// the engine's current index order (the spatial order of the last neighbour-list
// rebuild); contact histories are keyed by particle ids, in the pair's canonical
// orientation (lower id first), so they do not depend on that order.
//
// Materials, pair interactions and wall geometry are set up by whoever built the
// Simulation (the scene, from its config); the state carries copies only so that
// import_state() can refuse a state taken from a differently configured engine.
#include <cstdint>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/material.hpp"
#include "dem/motion.hpp"
#include "dem/vec3.hpp"

namespace centrec::dem {

struct PairHistoryEntry {
  std::int64_t id_lo = 0, id_hi = 0;  // particle ids, id_lo < id_hi
  ContactHistory history;             // non-zero (zero = not in contact, not stored)
};

// A particle's history with one wall (by the engine's wall index).
struct WallHistoryEntry {
  std::int64_t id = 0;
  int wall = 0;
  ContactHistory history;
};

struct SimulationState {
  double time = 0.0;        // s
  std::int64_t step = 0;    // steps taken
  double dt = 0.0;          // s, resolved time step
  std::int64_t next_id = 0; // id the next inserted particle gets
  double drum_angle = 0.0;  // rad turned by the drum (omega x time; glued particles carry it)

  // Configuration copies, checked on import.
  std::vector<Material> materials;
  std::vector<PairInteraction> interactions;  // n_mat x n_mat
  std::vector<Vec3> wall_origins;             // moving walls translate
  std::vector<Vec3> wall_force;               // N, last force pass (outputs read it)

  // Particles, index order.
  std::vector<std::int64_t> id;
  std::vector<int> material;
  std::vector<double> radius;                 // m
  std::vector<Motion> motion;
  std::vector<Vec3> x, v, w;                  // m, m/s, rad/s
  std::vector<Vec3> f, t;                     // N, N m: last force pass (the next half-kick uses them)

  std::vector<ContactHistory> wall_history;   // particles x walls, row-major
  std::vector<PairHistoryEntry> pair_history; // pairs in contact
};

}  // namespace centrec::dem
