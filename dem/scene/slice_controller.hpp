#pragma once
// Holdup controller of the periodic slice (docs/centrec_scene.md): the slice's axial mass
// flow mdot = sum(m_i v_z,i) / Ls (the flux through any cross-section, averaged over the
// period) is measured over a window of turns; at the window's end the holdup changes by
//   dN = gain x ln(target / mdot) x N,   |dN| <= max_step x N,
// adding packed co-rotating particles just inside the local film surface (never
// overlapping) or removing the particles nearest the axis (the free surface). mdot grows
// about as N^k with k ~ 2-4, so the loop gain k x gain stays below 2 (no divergence) for
// the default gain 0.25.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "dem/scene/size_distribution.hpp"
#include "dem/simulation.hpp"

namespace centrec::dem::scene {

// The slice's axial mass flow now, kg/s: sum over free particles of m v_z, over Ls.
double slice_axial_mass_flow(const Simulation& sim, double slice_length);

struct ControllerWindow {
  double time = 0.0;           // s, end of the window
  double mass_flow = 0.0;      // kg/s, mean over the window
  std::int64_t particles = 0;  // free particles after the adjustment
  std::int64_t change = 0;     // particles added (> 0) or removed (< 0)
};

struct SliceControllerState {
  double window_start = 0.0, flow_sum = 0.0;
  std::int64_t flow_samples = 0;
  std::string rng, size_rng;  // std::mt19937_64 stream format
  std::vector<ControllerWindow> log;
};

class SliceHoldupController {
 public:
  SliceHoldupController(const SceneConfig& config, MaterialId particle_material, double start_time);
  // After each batch of steps: accumulates mdot; at the window's end adjusts the holdup.
  void after_batch(Simulation& sim);
  const std::vector<ControllerWindow>& log() const { return state_.log; }
  SliceControllerState state() const;
  void restore(const SliceControllerState& s);

  // The two actuators (public for tests). Return how many particles were added/removed.
  std::int64_t insert(Simulation& sim, std::int64_t count);
  std::int64_t remove_surface(Simulation& sim, std::int64_t count);

 private:
  SceneConfig cfg_;
  MaterialId material_;
  double window_ = 0.0;  // s
  SizeSampler sizes_;
  std::mt19937_64 rng_;
  SliceControllerState state_;
};

}  // namespace centrec::dem::scene
