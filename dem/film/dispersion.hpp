#pragma once
// Wall-normal self-diffusion (dispersion) coefficient vs wall distance: the mixing part
// of the film's effective conductivity (docs/film_sampling.md "Wall-normal dispersion",
// docs/thermal_model.md "Mixing").
//
// Estimator: the slope of the mean squared displacement. Positions are sampled in bursts
// of equally spaced samples; each particle is followed by id. Two series of bursts share
// the tables: `fine` (spacing delta_f, much shorter than a snapshot interval: lags short
// against the bin-crossing time of the fast, loose top of the film) and `coarse` (the
// snapshots themselves: the longer lags the slow, dense bins need). For every pair of samples
// of a burst j spacings apart (lag tau = j delta, j = 1..lags of the series) a particle
// whose STARTING position lies in the axial window contributes its radial displacement
// dr = r(t + tau) - r(t) to the bin of its starting wall distance. Per bin and lag, with
// the mean drift removed,
//     MSD(tau) = <dr^2> - <dr>^2                                      (m^2)
// and D is half the slope of the least-squares line
//     MSD(tau) = 2 D tau + c                                          (m^2/s)
// over the bin's lags with tau <= crossing_fraction * t_x, t_x = w_bin^2 / (2 D) the time
// to diffuse across the bin (w_bin its width): lags short against the bin-crossing time,
// so the wall and the free surface do not bound the displacement and the particle stays
// where D is the bin's. t_x comes from D itself, so the lag range is iterated to a fixed
// point starting from the two shortest lags; at least those two are used (the bin then reports a lag range longer
// than crossing_fraction * t_x). The intercept c takes up the ballistic start of the MSD
// (c < 0) and position noise (c > 0).
//
// The spread is the standard deviation over periods (turns) of the same fit made on each
// period's own displacements over the same lags. Particles absent from either sample of a
// pair (inserted or removed in between) are skipped; no pair spans two bursts.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "dem/film/drum_frame.hpp"
#include "dem/film/packed_state.hpp"
#include "dem/film/particle_arrays.hpp"
#include "dem/film/wall_distance_bins.hpp"

namespace centrec::film {

struct DispersionConfig {
  WallDistanceBins bins;
  // Axial window of the starting positions, m (a drum's developed film; a slice: all).
  double z_min = -std::numeric_limits<double>::infinity();
  double z_max = std::numeric_limits<double>::infinity();
  int fine_lags = 20;               // lags 1..fine_lags spacings of the fine series
  int coarse_lags = 0;              // lags 1..coarse_lags spacings of the coarse series (0 = none)
  double crossing_fraction = 0.25;  // fit lags tau <= this x t_x: rms step <= sqrt(0.25) = half a bin
};

struct DispersionBin {
  double wall_distance_d = 0.0;  // bin centre, in d
  double coefficient = 0.0;      // D, m^2/s (NaN with fewer than 2 lags of data)
  double coefficient_std = 0.0;  // std over periods of the per-period fits, m^2/s (NaN with < 1 period)
  double drift = 0.0;            // -<dr>/tau at the shortest lag: wall-distance drift, m/s (> 0 away from the wall)
  double fit_lag_min = 0.0;      // s, the lag range of the fit
  double fit_lag_max = 0.0;      // s
  double crossing_time = 0.0;    // t_x = w_bin^2 / (2 D), s (inf for D <= 0)
  std::size_t samples = 0;       // displacements at the shortest lag
  std::size_t periods = 0;       // periods whose fit entered the spread
  std::vector<double> msd;       // per lag (DispersionEstimator::lags()), m^2 (NaN: < 2 displacements)
  std::vector<std::size_t> msd_samples;  // displacements per lag
};

// D from MSD(tau) = 2 D tau + c by least squares over the points (tau_j, msd_j) with
// tau_j <= tau_max; points with NaN are skipped. NaN with fewer than two points.
double msd_slope_coefficient(const std::vector<double>& tau, const std::vector<double>& msd, double tau_max);

enum class DispersionSeries : int { fine = 0, coarse = 1 };

class DispersionEstimator {
 public:
  DispersionEstimator(const DrumFrame& frame, DispersionConfig config);
  // One position sample of the series' current burst (needs x, y, z, id). Consecutive
  // samples of a burst must be the same spacing apart (the series' first pair sets it,
  // within 1e-6).
  void add_sample(const ParticleArrays& p, DispersionSeries series = DispersionSeries::fine);
  // The series' next sample starts a new burst.
  void end_burst(DispersionSeries series = DispersionSeries::fine);
  // Closes a period (a turn): its displacements become one sample of the spread.
  void end_period();
  double spacing(DispersionSeries s = DispersionSeries::fine) const { return series_[static_cast<int>(s)].spacing; }
  // s: the fine series' lags, then the coarse series' (0 while a series has no spacing yet).
  std::vector<double> lags() const;
  const DispersionConfig& config() const { return cfg_; }
  std::vector<DispersionBin> result() const;
  // Checkpoints (dem/film/packed_state.hpp): the sums and the per-period tables, not the
  // burst in progress (a loaded estimator starts a new burst).
  void save(PackedState& out) const;
  void load(StateReader& in);  // into an estimator built with the same config

  // Displacement sums per (bin, lag), row-major [bin * (fine_lags + coarse_lags) + lag].
  struct Table {
    std::vector<double> n, sum, sum2;
    void resize(std::size_t size);
    void add(const Table& other);
    bool empty() const;
    // MSD per lag of one bin (NaN where fewer than 2 displacements).
    std::vector<double> msd(int bin, int lags) const;
  };

 private:
  struct Position {
    std::int64_t id;
    double r, z;
  };
  struct Series {
    int lags = 0, offset = 0;  // its lags and its first column in the tables
    double spacing = 0.0, last_time = 0.0;
    std::vector<std::vector<Position>> burst;  // the last `lags` samples, each sorted by id
  };
  int total_lags() const { return cfg_.fine_lags + cfg_.coarse_lags; }
  DrumFrame frame_;
  DispersionConfig cfg_;
  Series series_[2];
  Table period_, all_;
  std::vector<Table> periods_;
};

}  // namespace centrec::film
