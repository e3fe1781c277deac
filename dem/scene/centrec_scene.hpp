#pragma once
// The CentRec scene (docs/centrec_scene.md): builds the engine's walls, rough wall and
// starting film from a SceneConfig, then advances it in batches, feeding particles at
// the inlet and removing those past the outlet, and logs the mass flows.
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "dem/scene/feeder.hpp"
#include "dem/scene/slice_controller.hpp"
#include "dem/scene/scene_config.hpp"
#include "dem/simulation.hpp"

namespace centrec::dem::scene {

// One entry per batch: cumulative masses since the start, kg.
struct MassFlowSample {
  double time = 0.0;           // s
  double fed = 0.0;            // kg inserted by the feeder so far
  double out = 0.0;            // kg that left through the outlet so far
  double lost = 0.0;           // kg removed elsewhere (escaped the drum) so far
  double holdup = 0.0;         // kg of free particles in the drum now
  std::int64_t particles = 0;  // free particles in the drum now
  double axial_flow = 0.0;     // kg/s; slice: sum(m v_z) / Ls now (0 for a drum)
};

// Gravity in the drum frame (axis +z, outlet at z = L): the tilt puts a component along +z.
Vec3 scene_gravity(const SceneConfig& c);

// Seconds per drum revolution.
inline double turn_period(const SceneConfig& c) { return 2.0 * M_PI / std::fabs(c.drum.omega); }

// The scene's dynamic state (checkpoints): the engine's plus what the scene carries.
struct SceneState {
  SimulationState engine;
  bool has_feeder = false;
  FeederState feeder;
  std::vector<MassFlowSample> mass_flow_log;
  double out_total = 0.0, lost_total = 0.0;  // kg
  bool has_controller = false;
  SliceControllerState controller;
};

// Wall-clock seconds of the scene's own work between engine steps (speed records).
struct SceneTimes {
  double insertion = 0.0;  // s: the feeder placing particles (and the engine taking them in)
  double outlet = 0.0;     // s: finding and removing the particles past the outlet
  double bookkeeping = 0.0;  // s: the slice controller and the mass-flow log
};

class CentrecScene {
 public:
  explicit CentrecScene(const SceneConfig& config);
  // Resumes a scene from a checkpoint taken of one built from the same config (the
  // starting film is not rebuilt; the engine refuses a state that does not fit).
  CentrecScene(const SceneConfig& config, const SceneState& state);
  // See Simulation::rebuild_lists(): call simulation().rebuild_lists() first for a
  // checkpoint a resumed run continues from bitwise.
  SceneState export_state() const;

  // Advance by `duration` seconds in feeder batches (the duration is rounded to whole steps).
  void advance(double duration);

  Simulation& simulation() { return *sim_; }
  const Simulation& simulation() const { return *sim_; }
  const SceneConfig& config() const { return cfg_; }
  MaterialId particle_material() const { return particle_material_; }  // every particle's
  const std::vector<MassFlowSample>& mass_flow_log() const { return log_; }
  const FeederStats& feeder_stats() const;
  // The slice holdup controller's windows (empty without a controller).
  const std::vector<ControllerWindow>& controller_log() const;

  double drum_radius() const { return 0.5 * cfg_.drum.diameter; }
  double turn_period() const;  // s per drum revolution
  std::int64_t steps_per_batch() const { return steps_per_batch_; }
  std::int64_t glued_particles() const { return glued_; }
  std::int64_t free_particles() const;
  double holdup_mass() const;  // kg of free particles
  const SceneTimes& times() const { return times_; }

 private:
  void build_engine();  // checks the config, creates the engine, its materials and walls
  void build_walls();
  void record(double out_mass, double lost_mass);

  SceneConfig cfg_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<Feeder> feeder_;
  std::unique_ptr<SliceHoldupController> controller_;  // slice with a target mass flow
  std::vector<MassFlowSample> log_;
  std::int64_t steps_per_batch_ = 1;
  std::int64_t glued_ = 0;
  // Set by build_engine (-1 until then: the engine refuses it).
  MaterialId particle_material_{-1}, wall_material_{-1};
  bool prefed_ = false;  // the first batch was fed before set-up
  double out_total_ = 0.0, lost_total_ = 0.0;
  SceneTimes times_;
};

}  // namespace centrec::dem::scene
