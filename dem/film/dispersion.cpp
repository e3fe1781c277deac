#include "dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dem/film/running_stats.hpp"

namespace centrec::film {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

double msd_slope_coefficient(const std::vector<double>& tau, const std::vector<double>& msd, double tau_max) {
  double n = 0.0, st = 0.0, sm = 0.0;
  for (std::size_t j = 0; j < msd.size(); ++j)
    if (std::isfinite(msd[j]) && tau[j] <= tau_max) n += 1.0, st += tau[j], sm += msd[j];
  if (n < 2.0) return kNaN;
  const double tm = st / n, mm = sm / n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t j = 0; j < msd.size(); ++j)
    if (std::isfinite(msd[j]) && tau[j] <= tau_max) {
      sxx += (tau[j] - tm) * (tau[j] - tm);
      sxy += (tau[j] - tm) * (msd[j] - mm);
    }
  return sxx > 0.0 ? 0.5 * sxy / sxx : kNaN;  // MSD = 2 D tau + c
}

void DispersionEstimator::Table::resize(std::size_t size) {
  n.assign(size, 0.0);
  sum.assign(size, 0.0);
  sum2.assign(size, 0.0);
}

void DispersionEstimator::Table::add(const Table& o) {
  for (std::size_t i = 0; i < n.size(); ++i) n[i] += o.n[i], sum[i] += o.sum[i], sum2[i] += o.sum2[i];
}

bool DispersionEstimator::Table::empty() const {
  return std::all_of(n.begin(), n.end(), [](double v) { return v == 0.0; });
}

std::vector<double> DispersionEstimator::Table::msd(int bin, int lags) const {
  std::vector<double> out(static_cast<std::size_t>(lags), kNaN);
  for (int j = 0; j < lags; ++j) {
    const std::size_t i = static_cast<std::size_t>(bin * lags + j);
    if (n[i] < 2.0) continue;
    const double m = sum[i] / n[i];
    out[static_cast<std::size_t>(j)] = std::max(0.0, sum2[i] / n[i] - m * m);  // the variance of dr
  }
  return out;
}

DispersionEstimator::DispersionEstimator(const DrumFrame& frame, DispersionConfig config)
    : frame_(frame), cfg_(config) {
  cfg_.bins.check("DispersionEstimator");
  if (cfg_.fine_lags < 0 || cfg_.coarse_lags < 0 || total_lags() < 2)
    throw std::invalid_argument("DispersionEstimator: needs at least two lags (a slope) over both series");
  if (!(cfg_.crossing_fraction > 0.0)) throw std::invalid_argument("DispersionEstimator: crossing_fraction must be > 0");
  if (!(cfg_.z_max > cfg_.z_min)) throw std::invalid_argument("DispersionEstimator: the axial window is empty");
  series_[0].lags = cfg_.fine_lags;
  series_[1].lags = cfg_.coarse_lags;
  series_[1].offset = cfg_.fine_lags;
  const std::size_t size = static_cast<std::size_t>(cfg_.bins.count) * static_cast<std::size_t>(total_lags());
  period_.resize(size);
  all_.resize(size);
}

void DispersionEstimator::add_sample(const ParticleArrays& p, DispersionSeries which) {
  require_arrays(p, "xyzi", "DispersionEstimator");
  Series& se = series_[static_cast<int>(which)];
  if (se.lags == 0) return;  // a series without lags takes nothing
  if (!se.burst.empty()) {
    const double step = p.time - se.last_time;
    if (!(step > 0.0)) throw std::invalid_argument("DispersionEstimator: samples of a burst must advance in time");
    if (se.spacing == 0.0) se.spacing = step;
    if (std::fabs(step - se.spacing) > 1e-6 * se.spacing)
      throw std::invalid_argument("DispersionEstimator: the samples of every burst must be the same spacing apart");
  }
  std::vector<Position> now(p.count);
  for (std::size_t i = 0; i < p.count; ++i) now[i] = {p.id[i], std::hypot(p.x[i], p.y[i]), p.z[i]};
  std::sort(now.begin(), now.end(), [](const Position& a, const Position& b) { return a.id < b.id; });

  // Pair with each earlier sample of the burst: j spacings back is lag j (column offset + j - 1).
  const int columns = total_lags();
  for (std::size_t back = 1; back <= se.burst.size(); ++back) {
    const std::vector<Position>& start = se.burst[se.burst.size() - back];
    const int j = se.offset + static_cast<int>(back) - 1;
    std::size_t e = 0;
    for (const Position& s : start) {  // both sorted by id: one merge pass
      if (!(s.z >= cfg_.z_min && s.z <= cfg_.z_max)) continue;
      while (e < now.size() && now[e].id < s.id) ++e;
      if (e == now.size()) break;
      if (now[e].id != s.id) continue;
      const int k = cfg_.bins.index(frame_.radius - s.r);
      if (k < 0) continue;
      const double dr = now[e].r - s.r;
      const std::size_t i = static_cast<std::size_t>(k * columns + j);
      period_.n[i] += 1.0;
      period_.sum[i] += dr;
      period_.sum2[i] += dr * dr;
    }
  }
  se.burst.push_back(std::move(now));
  if (se.burst.size() > static_cast<std::size_t>(se.lags)) se.burst.erase(se.burst.begin());
  se.last_time = p.time;
}

void DispersionEstimator::end_burst(DispersionSeries which) { series_[static_cast<int>(which)].burst.clear(); }

void DispersionEstimator::end_period() {
  if (!period_.empty()) {
    all_.add(period_);
    periods_.push_back(period_);
  }
  period_.resize(period_.n.size());
}

std::vector<double> DispersionEstimator::lags() const {
  std::vector<double> tau;
  for (const Series& se : series_)
    for (int j = 1; j <= se.lags; ++j) tau.push_back(j * se.spacing);
  return tau;
}

std::vector<DispersionBin> DispersionEstimator::result() const {
  const int columns = total_lags();
  const std::vector<double> tau = lags();
  Table pooled = all_;
  pooled.add(period_);  // a period still open counts too
  const double w = cfg_.bins.width_m();
  std::vector<DispersionBin> out(static_cast<std::size_t>(cfg_.bins.count));
  for (int k = 0; k < cfg_.bins.count; ++k) {
    DispersionBin& b = out[static_cast<std::size_t>(k)];
    b.wall_distance_d = cfg_.bins.centre_d(k);
    b.msd = pooled.msd(k, columns);
    for (int j = 0; j < columns; ++j)
      b.msd_samples.push_back(static_cast<std::size_t>(pooled.n[static_cast<std::size_t>(k * columns + j)]));
    b.coefficient = b.coefficient_std = b.drift = b.fit_lag_min = b.fit_lag_max = b.crossing_time = kNaN;
    // The lags with data, shortest first.
    std::vector<std::size_t> valid;
    for (std::size_t j = 0; j < tau.size(); ++j)
      if (std::isfinite(b.msd[j]) && tau[j] > 0.0) valid.push_back(j);
    std::sort(valid.begin(), valid.end(), [&](std::size_t a, std::size_t c) { return tau[a] < tau[c]; });
    b.samples = valid.empty() ? 0 : b.msd_samples[valid.front()];
    if (valid.size() < 2) continue;
    {
      const std::size_t i = static_cast<std::size_t>(k * columns) + valid.front();
      b.drift = -pooled.sum[i] / pooled.n[i] / tau[valid.front()];  // dw = -dr
    }
    // Lags short against the bin-crossing time: from the two shortest lags, widen (or
    // narrow) the range to the lags <= crossing_fraction * t_x of the current D until it
    // stops changing. Starting short matters: where the MSD saturates or falls at long lags
    // (a thin loose top, particles falling back), a fit over every lag gives D <= 0, an
    // infinite t_x, and would keep every lag.
    const double floor_lag = tau[valid[1]];
    double tau_max = floor_lag;
    double D = msd_slope_coefficient(tau, b.msd, tau_max);
    for (std::size_t it = 0; it < valid.size(); ++it) {
      const double tx = D > 0.0 ? w * w / (2.0 * D) : kInf;
      double next = floor_lag;
      for (std::size_t j : valid)
        if (tau[j] <= cfg_.crossing_fraction * tx) next = std::max(next, tau[j]);
      if (next == tau_max) break;
      tau_max = next;
      D = msd_slope_coefficient(tau, b.msd, tau_max);
    }
    b.coefficient = D;
    b.crossing_time = D > 0.0 ? w * w / (2.0 * D) : kInf;
    b.fit_lag_min = tau[valid.front()];
    b.fit_lag_max = tau_max;
    RunningStats spread;
    for (const Table& t : periods_) {
      const double d = msd_slope_coefficient(tau, t.msd(k, columns), tau_max);
      if (std::isfinite(d)) spread.add(d);
    }
    b.periods = spread.count();
    b.coefficient_std = spread.stddev();
  }
  return out;
}

void DispersionEstimator::save(PackedState& out) const {
  // The open bursts too: a checkpoint inside a sampled turn holds the coarse series' earlier
  // snapshots of that turn, and the resumed run pairs them as the uninterrupted one does.
  for (const Series& se : series_) {
    out.put(se.spacing);
    out.put(se.last_time);
    out.put(static_cast<double>(se.burst.size()));
    for (const std::vector<Position>& sample : se.burst) {
      out.put(static_cast<double>(sample.size()));
      for (const Position& q : sample) out.put(static_cast<double>(q.id)), out.put(q.r), out.put(q.z);
    }
  }
  for (const Table* t : {&period_, &all_}) {
    out.put_all(t->n);
    out.put_all(t->sum);
    out.put_all(t->sum2);
  }
  out.put(static_cast<double>(periods_.size()));
  for (const Table& t : periods_) {
    out.put_all(t.n);
    out.put_all(t.sum);
    out.put_all(t.sum2);
  }
}

void DispersionEstimator::load(StateReader& in) {
  const std::size_t size = all_.n.size();
  auto read = [&](Table& t) {
    in.get_all(t.n);
    in.get_all(t.sum);
    in.get_all(t.sum2);
    if (t.n.size() != size || t.sum.size() != size || t.sum2.size() != size)
      throw std::invalid_argument("DispersionEstimator: saved state has a different bin or lag count");
  };
  for (Series& se : series_) {
    se.spacing = in.get();
    se.last_time = in.get();
    se.burst.assign(in.count(), {});
    for (std::vector<Position>& sample : se.burst) {
      sample.resize(in.count());
      for (Position& q : sample) {
        q.id = static_cast<std::int64_t>(in.get());  // ids are below 2^53: exact in a double
        q.r = in.get();
        q.z = in.get();
      }
    }
  }
  read(period_);
  read(all_);
  periods_.assign(in.count(), Table{});
  for (Table& t : periods_) read(t);
}

}  // namespace centrec::film
