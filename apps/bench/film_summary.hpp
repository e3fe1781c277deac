#pragma once
// The film's state from particle arrays, computed as the LIGGGHTS deck computes it.
#include "bench/engine_result.hpp"
#include "bench/film_case.hpp"

namespace centrec::bench {

// Fills everything but pair_contacts (the engine counts those). x, v, w: n particles of
// 3 contiguous doubles each (x0 y0 z0 x1 ...); mass and moment of inertia per particle.
FilmSummary summarize_film(const FilmCase& c, long n, const double* x, const double* v, const double* w,
                           double mass, double inertia);

}  // namespace centrec::bench
