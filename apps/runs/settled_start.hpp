#pragma once
// dem.initial_film.from_run: the free particles of an earlier `centrec dem` run's last
// state (its checkpoint.h5) for this case's drum (dem/scene/settled_start.hpp).
#include <vector>

#include "config/case_dem.hpp"
#include "config/case_file.hpp"

namespace centrec::runs {

// The settled film for dc's drum from the run named by dc.initial_film_from_run (relative
// to cf's folder). Throws config::ConfigError naming the key and the reason.
std::vector<dem::scene::InitialFilmSpec::Particle> settled_start(const config::CaseFile& cf, const config::DemCase& dc);

}  // namespace centrec::runs
