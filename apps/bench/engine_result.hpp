#pragma once
// What one engine run of the benchmark yields, whichever engine ran it.
#include <string>
#include <vector>

namespace centrec::bench {

// The film's state, computed the same way for both engines (see film_summary.hpp and
// the LIGGGHTS deck's state report), to show that both advanced the same system.
struct FilmSummary {
  long atoms = 0;
  double kinetic_energy = 0.0;     // translational, J
  double rotational_energy = 0.0;  // J
  double mean_speed = 0.0;         // mean |v|, m/s
  double mean_omega_z = 0.0;       // mean of (x vy - y vx)/(x^2 + y^2): drum co-rotation, rad/s
  double min_radius = 0.0;         // innermost particle centre, m (film free surface)
  double max_radius = 0.0;         // outermost particle centre, m (< R: nobody left the drum)
  double mean_vz = 0.0;            // mean axial velocity, m/s (film drainage)
  double pair_contacts = 0.0;      // particle pairs overlapping
  double wall_contacts = 0.0;      // particles whose centre is within d/2 of the cylinder
};

struct EngineResult {
  std::string engine;              // "centrec" or "LIGGGHTS"
  int workers = 1;                 // OpenMP threads or MPI ranks
  long particles = 0;
  long steps = 0;                  // steps per timed phase
  std::vector<double> seconds;     // wall time of each timed phase
  double bytes_per_particle = 0.0; // engine-reported memory / N
  double rss_bytes_per_particle = 0.0;  // centrec only: RSS growth / N (0 if unknown)
  // Work done besides the contacts: neighbour pairs in the list (each pair once) per
  // particle at the end, and neighbour-list rebuilds per timed phase (mean).
  double list_pairs_per_particle = 0.0;
  double rebuilds_per_phase = 0.0;
  FilmSummary settled, final;
  std::string note;                // e.g. why a run failed
  bool ok = false;

  double median_seconds() const;
  double particle_steps_per_second() const;  // particles * steps / median
};

}  // namespace centrec::bench
