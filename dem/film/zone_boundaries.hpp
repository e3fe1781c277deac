#pragma once
// Moving and stationary zones of the film (paper Fig 4): the angles where the
// tangentially binned surface axial velocity crosses a threshold, a fraction of its
// maximum. Input: one value per tangential bin, bin k centred at theta = (k + 0.5) 2 pi / n
// (e.g. FilmThicknessAccumulator::surface_velocity). Crossings are located by linear
// interpolation between neighbouring bin centres, cyclically. Empty (NaN) bins count as
// stationary.
//
// Theta grows against the rotation (drum_frame.hpp), so the wall carries material
// through a moving arc from its larger-theta edge (`start`, where the film begins to
// flow) to its smaller-theta edge (`end`, where it stops).
#include <cstddef>
#include <vector>

namespace centrec::film {

struct MovingArc {
  double start = 0.0;  // rad in [0, 2 pi): the film starts moving here (upstream edge)
  double end = 0.0;    // rad in [0, 2 pi): and stops here (downstream edge)
  double width() const;  // rad, from end to start in the theta direction
};

struct ZoneDetection {
  double threshold = 0.0;         // m/s: fraction * max surface velocity
  std::vector<MovingArc> moving;  // ordered by `end`; empty if no bin or every bin moves
  std::vector<int> zone_of_bin;   // 1 moving, 0 stationary (input to SolidFractionSampler)
};

// Throws std::invalid_argument if n == 0, fraction not in (0, 1], or no bin is finite
// and positive (no flow, nothing to threshold).
ZoneDetection detect_zones(const double* surface_vz, std::size_t n, double threshold_fraction);

}  // namespace centrec::film
