#pragma once
// DIR/dem.h5 of a DEM run (docs/outputs.md) and its XDMF sidecar DIR/dem.xmf so
// ParaView opens the particle snapshots. Units are attributes of every dataset.
//
// Layout:
//   /mass_flow/{time, fed, out, lost, holdup, particles}   cumulative masses vs time
//   /film/...       averaged film fields over the sampled turns (absent without sampling)
//   /snapshots/<name>/{position [N,3], velocity [N,3], radius, id}
//   root attributes: code_version, engine, engine_version, case, resolved_config,
//                    drum_radius_m, particle_diameter_m, turn_period_s
#include <string>
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "io/dem_run_result.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

void write_dem_h5(const std::string& dir, const std::string& case_path, const std::string& resolved_yaml,
                  const dem::scene::SceneConfig& scene, const DemRunResult& run);

// /mass_flow of an open dem.h5 (time, fed and out; the rest stays zero).
std::vector<dem::scene::MassFlowSample> read_mass_flow_log(const H5File& f);

}  // namespace centrec::io
