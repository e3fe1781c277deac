#pragma once
// Film thickness (paper eqs 4-7) and surface axial velocity on a grid of axial sections
// x tangential bins, for one snapshot, and their mean and standard deviation over
// snapshots (paper Fig 3: thickness along z averaged over 150 turns, error bar = std).
#include <cstddef>
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/film_thickness.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/running_stats.hpp"

namespace centrec::film {

struct FilmSectionGrid {
  int axial_sections = 20;      // equal sections over [z_min, z_max]
  int tangential_bins = 36;     // equal bins over theta in [0, 2 pi)
  double z_min = 0.0;           // m
  double z_max = -1.0;          // m; < 0 means the drum length
  double particle_diameter = 0.0;  // m; 0 = the snapshot's mean 2 * radius
  double solid_fraction = 0.5;     // f_s of eq (5)
};

// One snapshot. Cell index = axial * tangential_bins + tangential. NaN where empty.
struct FilmSectionSnapshot {
  int axial_sections = 0;
  int tangential_bins = 0;
  double particle_diameter = 0.0;        // m, d used in eqs (5), (7)
  std::vector<double> ring_thickness;    // [axial] eqs 4-7 on the full ring, m
  std::vector<double> cell_thickness;    // [cell] eqs 4-7 with the bin's arc fraction, m
  std::vector<double> cell_surface_vz;   // [cell] mean vz of the cell's n_p surface particles, m/s
  std::vector<std::size_t> cell_count;   // [cell] particles with centres in the cell
};

// Needs x, y, z, radius, and vz (for the surface velocity).
FilmSectionSnapshot sample_film_sections(const ParticleArrays& p, const DrumFrame& frame, const FilmSectionGrid& grid);

struct LengthStat {
  double mean_m = 0.0, std_m = 0.0;   // m
  double mean_d = 0.0, std_d = 0.0;   // in particle diameters
  std::size_t samples = 0;            // snapshots that had particles there
};

// Collects snapshots (call once per snapshot, e.g. once per turn after steady state).
class FilmThicknessAccumulator {
 public:
  void add(const FilmSectionSnapshot& s);
  std::size_t snapshots() const { return snapshots_; }
  int axial_sections() const { return n_ax_; }
  int tangential_bins() const { return n_tan_; }
  double particle_diameter() const { return d_.mean(); }

  LengthStat ring(int axial) const;                 // tangentially whole section
  LengthStat cell(int axial, int tangential) const; // one tangential bin
  // Mean over snapshots of the section-averaged thickness (the drum's mean film).
  LengthStat overall() const;
  // Surface axial velocity per tangential bin, mean over snapshots and over the axial
  // sections [axial_lo, axial_hi); input to zone detection.
  std::vector<double> surface_velocity(int axial_lo, int axial_hi) const;
  const RunningStats& surface_velocity_cell(int axial, int tangential) const;
  void save(PackedState& out) const;  // checkpoints (dem/film/packed_state.hpp)
  void load(StateReader& in);         // into a sampler built with the same config

 private:
  LengthStat to_length(const RunningStats& s) const;
  int n_ax_ = 0, n_tan_ = 0;
  std::size_t snapshots_ = 0;
  RunningStats d_;
  std::vector<RunningStats> ring_, cell_, vz_;
  RunningStats overall_;
};

}  // namespace centrec::film
