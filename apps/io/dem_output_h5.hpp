#pragma once
// DIR/dem.h5 of a DEM run (docs/outputs.md) and its XDMF sidecars DIR/dem.xmf (the particle
// snapshots) and DIR/drum.xmf (the drum surface) for ParaView. Units are attributes of every
// dataset; 1D axes are HDF5 dimension scales of the datasets over them. /mass_flow and
// /film are written from one schema list each (name, unit, scale, reader) and read back
// from the same lists.
//
// Layout:
//   /mass_flow/{time, fed, out, lost, holdup, particles}   cumulative masses vs time
//   /film/...       averaged film fields over the sampled turns (absent without sampling)
//   /snapshots/<name>/{position [N,3], velocity [N,3], radius, id, glued, vertex}
//   /drum/{points [P,3], triangles [T,3]}                  the drum's inner surface
//   root attributes: the provenance (io/provenance.hpp), engine, engine_version,
//                    drum_radius_m, particle_diameter_m, turn_period_s
#include <string>
#include <vector>

#include "dem/scene/scene_config.hpp"
#include "io/dem_run_result.hpp"
#include "io/h5_file.hpp"
#include "io/provenance.hpp"

namespace centrec::io {

void write_dem_h5(const std::string& dir, const Provenance& provenance, const dem::scene::SceneConfig& scene,
                  const DemRunResult& run);

// Read back from an open dem.h5 by the same schema lists that write it: /mass_flow whole,
// and of /film what the coupling uses (dem/scene/scene_sampler.hpp SampledFilm; the rest
// stays empty). Throw std::runtime_error naming the missing or inconsistent dataset.
std::vector<dem::scene::MassFlowSample> read_mass_flow_log(const H5File& f);
dem::scene::SampledFilm read_film_fields(const H5File& f);

}  // namespace centrec::io
