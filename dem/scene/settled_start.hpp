#pragma once
// A settled start (docs/centrec_scene.md "Settled start"): a drum started from the film it
// will have instead of a loose lattice that drains for turns before it settles. The free
// particles of an earlier run's last state, on the same drum diameter and rough wall:
// a slice's film laid end to end along the drum (its holdup per length), or a drum's film
// (a nearby operating point's, cut to the drum's length). The glued lattice of the state
// has turned with the drum; the particles are turned back with it so they sit in the new
// scene's lattice (built at angle 0) as they sat in the old, and their motion is re-based
// from the old drum speed to the new (the same velocity relative to the wall).
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "dem/simulation_state.hpp"

namespace centrec::dem::scene {

// The initial film of `target` (a drum) from `state`, the last state of a run of `source`:
// its free particles in `settled`, and, when the source is a drum, their contact histories
// with each other, with the glued spheres (matched by lattice position) and with the walls
// (when both drums have the same walls), turned back with the drum as the particles are.
// Throws std::invalid_argument naming the setting that differs (drum diameter, rough wall,
// particle size, a slice whose lattice rows do not continue along the drum) or when the
// target is a slice. A slice copy that would cross the back plate or the outlet is left
// out, and so is a drum particle past the target's length.
InitialFilmSpec settled_film(const SceneConfig& source, const SimulationState& state, const SceneConfig& target);

}  // namespace centrec::dem::scene
