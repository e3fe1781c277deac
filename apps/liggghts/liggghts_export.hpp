#pragma once
// `centrec export-liggghts`: a complete, commented LIGGGHTS 3.8 deck for a DEM case
// (docs/architecture.md): the data file (rough-wall glued spheres and the starting film,
// exactly as the native scene builds them), the drum STL (cylinder, back plate, outlet
// lip) and the outlet counting face written from the analytic geometry, and in.centrec.
// Settings LIGGGHTS cannot express are refused by name.
#include <cstdint>
#include <string>
#include <vector>

#include "config/case_dem.hpp"
#include "config/case_file.hpp"
#include "dem/scene/centrec_scene.hpp"

namespace centrec::liggghts {

// What the deck does, so a run can read its outputs back. Paths are relative to the
// export directory.
struct LiggghtsDeckPlan {
  double dt = 0.0;                 // s
  std::int64_t spinup_steps = 0;   // run.duration rounded up to whole snapshot intervals
  std::int64_t sampling_steps = 0;
  std::int64_t dump_every = 0;     // steps between film snapshots (turn period / snapshots_per_turn)
  std::int64_t flow_every = 0;     // steps between mass-flow records (feeder interval)
  int sampled_turns = 0;
  int snapshots_per_turn = 0;
  std::int64_t glued = 0, initial_free = 0;
  double initial_holdup = 0.0;     // kg of free particles in the data file
  std::string deck = "in.centrec", data = "data.centrec", drum_stl = "drum.stl", ends_stl = "drum_ends.stl",
              outlet_stl = "outlet.stl";
  int drum_facets_around = 0, drum_facets_axial = 0;
  double drum_curvature_deg = 0.0;  // fix mesh/surface curvature of the cylinder (liggghts_stl)
  bool has_ends = false;            // back plate and/or outlet lip present (drum_ends.stl)
  std::string dump_dir = "dumps", dump_pattern = "dumps/film_*.dump", flow_file = "mass_flow.txt";
  std::string log = "log.liggghts", screen = "screen.liggghts";
  // What the deck runs differently from the native scene, one sentence each (written into
  // the deck and printed by the commands that write it).
  std::vector<std::string> differences;
};

// What a deck of this case runs differently from the native engine, without refusing it.
std::vector<std::string> liggghts_differences(const config::DemCase& dc);

// Every setting of the case LIGGGHTS 3.8 cannot express, one message each (empty: fine).
std::vector<std::string> liggghts_inexpressible(const config::DemCase& dc);

// Writes the deck, data file and STL files into dir (created); throws
// std::invalid_argument listing the inexpressible settings. The data file holds the
// case's starting particles, or with `start` the particles of that state (a checkpoint of
// a run of the same case: the benchmark starts both engines from a steady drum).
LiggghtsDeckPlan export_liggghts(const config::CaseFile& cf, const config::DemCase& dc, const std::string& dir,
                                 const dem::scene::SceneState* start = nullptr);

}  // namespace centrec::liggghts
