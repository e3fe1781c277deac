#pragma once
// Configuration of the CentRec scene (docs/centrec_scene.md): the tilted rotating drum,
// its retention hardware (outlet lip, rough wall), the feeder, the outlet and the
// periodic-slice mode.
//
// Frame: the drum axis is +z, from the inlet (back plate, z = 0) to the outlet (z = L).
// Gravity is g (0, -cos(tilt), +sin(tilt)): its transverse part points to -y ("down" in
// the cross-section) and its axial part drives the film toward the outlet. The drum
// spins at omega about +z (counter-clockwise seen from the outlet looking toward the
// inlet). Angles in the cross-section are atan2(y, x) in that same sense unless a sampler
// states otherwise.
#include <cstdint>
#include <vector>

#include "dem/material.hpp"
#include "dem/simulation.hpp"

namespace centrec::dem::scene {

enum class SizeDistribution : std::uint8_t { mono, uniform, normal };

struct ParticleSpec {
  double diameter = 1.2e-3;  // mean diameter, m (paper Table 1)
  SizeDistribution distribution = SizeDistribution::mono;
  double relative_spread = 0.0;  // uniform: half-width / mean; normal: std / mean (cut at 3 sigma)
  Material material;             // paper Table 1 defaults
};

struct DrumSpec {
  double diameter = 0.12;     // m
  double length = 0.171;      // m
  double tilt = 0.785398163397448;  // rad from horizontal (paper: 45 deg)
  double omega = 16.7636;     // rad/s (paper D12: 160.08 rpm)
  bool back_plate = true;     // disc closing the inlet end
  double lip_height = 0.0;    // m; annular weir at the outlet end (0 = open outlet)
};

enum class Lattice : std::uint8_t { square, hexagonal };

// A monolayer of spheres glued to the rotating wall (the wire mesh's job in the receiver).
struct RoughWallSpec {
  bool enabled = false;
  Lattice lattice = Lattice::square;
  double spacing = 1.2e-3;          // centre distance between neighbours, m
  double sphere_diameter = 1.2e-3;  // m
};

struct FeederSpec {
  bool enabled = true;
  double mass_flow = 35.7e-3;    // kg/s
  double radial_offset = 12e-3;  // m: centre of the feeder region inside the wall (paper: 10 d)
  double angle = 0.0;            // rad: atan2(y, x) of the feeder centre
  double axial_start = 1.2e-3;   // m from the back plate
  double axial_length = 6e-3;    // m
  double radial_height = 2.4e-3; // m
  double arc_width = 12e-3;      // m
  double interval = 1e-3;        // s between insertion batches
  int max_attempts = 60;         // random positions tried per particle before deferring it
};

// The starting film: a loose lattice co-rotating with the drum (slices always; drums
// optionally, to reach steady state sooner).
struct InitialFilmSpec {
  std::int64_t particles = 0;  // 0 = start empty
  double axial_from = 0.0;     // m (drum mode; the slice fills its whole period)
  double axial_to = 0.0;       // m; 0 = drum length
  // A settled start instead of the loose lattice: free particles laid in from an earlier
  // run's last state (dem/scene/settled_start.hpp), set by the run from
  // dem.initial_film.from_run. Empty: the loose lattice of `particles`.
  struct Particle {
    double radius = 0.0;  // m
    Vec3 x, v, w;         // m, m/s, rad/s
    std::int64_t source_id = -1;  // its id in the run it comes from
  };
  std::vector<Particle> settled;
  // The settled film's contact histories (a drum's film only), numbered as the scene adds
  // its particles: the glued spheres 0..G-1 in lattice order, then `settled` in order.
  std::vector<PairHistoryEntry> settled_contacts;
  std::vector<WallHistoryEntry> settled_wall_contacts;
  // Fraction of the settled film kept in every axial section of one diameter, its top (the
  // particles nearest the axis) left out: a fed drum holds less than the developed film of
  // the slice it is laid from (docs/centrec_scene.md "Settled start"). 1 keeps all.
  double holdup_fraction = 1.0;
};

// Axially periodic slice of the drum: no feeder, no outlet, no plates.
struct SliceSpec {
  bool enabled = false;
  double length = 24e-3;  // m (period)
  // Holdup controller (dem/scene/slice_controller.hpp): after every window of turns,
  // adds packed co-rotating particles at the film surface or removes surface particles
  // until the axial mass flow sum(m v_z) / length matches the target.
  double target_mass_flow = 0.0;  // kg/s; 0 = off (the holdup stays as started)
  double controller_gain = 0.25;  // holdup change per window = gain x ln(target / flow) x holdup
  double controller_window_turns = 1.0;  // turns per measurement window
  double controller_max_step = 0.1;      // largest holdup change per window, fraction of the holdup
};

struct SceneConfig {
  ParticleSpec particle;
  Material wall_material;
  PairInteraction particle_particle;                 // paper Table 1
  PairInteraction particle_wall{0.46, 10000.0, 0.26};
  // paper: wall friction 10000
  WallRolling wall_rolling = WallRolling::relative;
  DrumSpec drum;
  RoughWallSpec rough_wall;
  FeederSpec feeder;
  InitialFilmSpec initial_film;
  SliceSpec slice;
  double gravity = 9.81;  // m/s^2
  double dt = 0.0;        // s; 0 = the engine's recommended step
  double max_impact_speed = 2.0;  // m/s, for the time-step advice
  double skin = 0.0;              // Verlet skin in m; 0 = the engine's default (0.2 d)
  int threads = 0;
  std::uint64_t seed = 12345;
};

// The flow a scene is run at: the slice controller's target in slice mode, else the feed.
inline double target_mass_flow(const SceneConfig& c) {
  return c.slice.enabled ? c.slice.target_mass_flow : c.feeder.mass_flow;
}
inline void set_target_mass_flow(SceneConfig& c, double mdot) {
  (c.slice.enabled ? c.slice.target_mass_flow : c.feeder.mass_flow) = mdot;
}

}  // namespace centrec::dem::scene
