#pragma once
// dem.initial_film.from_run: the free particles of an earlier `centrec dem` run's last
// state (its checkpoint.h5) for this case's drum (dem/scene/settled_start.hpp).
#include <vector>

#include "config/case_dem.hpp"
#include "config/case_file.hpp"

#include "io/checkpoint_h5.hpp"

namespace centrec::runs {

// The dem: and receiver: sections of the case a checkpoint's run used, as a case of its own:
// the drum that ran (its other sections may hold keys of another version of this program).
// Throws std::invalid_argument if it has no dem: section.
config::CaseFile drum_case_of(const io::RunCheckpoint& ck);

// dc's initial film, settled from the run named by dc.initial_film_from_run (relative to
// cf's folder): its particles and their contact histories. Throws config::ConfigError
// naming the key and the reason.
dem::scene::InitialFilmSpec settled_start(const config::CaseFile& cf, const config::DemCase& dc);

}  // namespace centrec::runs
