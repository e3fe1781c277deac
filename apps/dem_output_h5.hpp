#pragma once
// DIR/dem.h5 of a DEM run (DESIGN.md section 7) and its XDMF sidecar DIR/dem.xmf so
// ParaView opens the particle snapshots. Units are attributes of every dataset.
//
// Layout:
//   /mass_flow/{time, fed, out, lost, holdup, particles}   cumulative masses vs time
//   /film/...       averaged film fields over the sampled turns (absent without sampling)
//   /snapshots/<name>/{position [N,3], velocity [N,3], radius, id}
//   root attributes: code_version, case, resolved_config
#include <string>
#include <vector>

#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/scene_sampler.hpp"

namespace centrec::cli {

struct NamedSnapshot {
  std::string name;  // group name, e.g. "t0.500000"
  dem::scene::SnapshotArrays data;
};

void write_dem_h5(const std::string& dir, const std::string& case_path, const std::string& resolved_yaml,
                  const dem::scene::CentrecScene& scene, const dem::scene::FilmFields& fields,
                  const std::vector<NamedSnapshot>& snapshots);

}  // namespace centrec::cli
