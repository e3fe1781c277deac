#include "dem/scene/scene_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dem/film/developed_film.hpp"

namespace centrec::dem::scene {

SnapshotArrays take_snapshot(const Simulation& sim) {
  SnapshotArrays s;
  s.time = sim.time();
  const std::size_t n = sim.size();
  for (auto* v : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.radius}) v->reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (sim.motions()[i] != Motion::free) continue;  // the glued layer is wall, not film
    const Vec3 x = sim.positions()[i], v = sim.velocities()[i];
    s.x.push_back(x.x);
    s.y.push_back(x.y);
    s.z.push_back(x.z);
    s.vx.push_back(v.x);
    s.vy.push_back(v.y);
    s.vz.push_back(v.z);
    s.radius.push_back(sim.radii()[i]);
    s.id.push_back(sim.ids()[i]);
  }
  return s;
}

SceneSampler::SceneSampler(const SceneConfig& c, const SamplingSpec& spec) : spec_(spec) {
  const bool slice = c.slice.enabled;
  const double length = slice ? c.slice.length : c.drum.length;
  const Vec3 g = scene_gravity(c);
  frame_ = film::DrumFrame::from_gravity(0.5 * c.drum.diameter, length, g.x, g.y, c.drum.omega);
  const double d = c.particle.diameter;

  grid_.axial_sections = slice ? 1 : spec.axial_sections;
  grid_.tangential_bins = spec.tangential_bins;
  grid_.particle_diameter = d;
  grid_.z_max = length;

  film::WallDistanceBins bins;
  bins.width_d = spec.bin_width_d;
  bins.count = spec.bins;
  bins.particle_diameter = d;

  film::VelocityProfileConfig vc;
  vc.bins = bins;
  if (slice) {  // a slice is one axial position: the three arcs over its whole period
    vc.sections = {{45 * M_PI / 180, 0.5}, {90 * M_PI / 180, 0.5}, {135 * M_PI / 180, 0.5}};
    vc.axial_half_length = 0.5;
  }
  velocity_ = std::make_unique<film::VelocityProfileSampler>(frame_, vc);

  film::SolidFractionConfig sc;
  sc.bins = bins;
  sc.zone_of_bin.resize(static_cast<std::size_t>(spec.tangential_bins));
  std::iota(sc.zone_of_bin.begin(), sc.zone_of_bin.end(), 0);
  sc.z_max = length;
  if (!slice) {  // away from the feeder and the outlet
    sc.z_min = film::kDevelopedFrom * length;
    sc.z_max = film::kDevelopedTo * length;
  }
  solid_ = std::make_unique<film::SolidFractionSampler>(frame_, sc);

  film::DispersionConfig dc;
  dc.bins = bins;
  dc.fine_lags = spec.dispersion_lags;
  dc.coarse_lags = spec.snapshots_per_turn - 1;
  if (!slice) {  // the developed film only; a slice is developed everywhere
    dc.z_min = film::kDevelopedFrom * length;
    dc.z_max = film::kDevelopedTo * length;
  }
  dispersion_ = std::make_unique<film::DispersionEstimator>(frame_, dc);

  film::RingProfileConfig rc;
  rc.bins = bins;
  rc.sections = grid_.axial_sections;
  rc.z_max = length;
  ring_ = std::make_unique<film::RingProfileSampler>(frame_, rc);
}

void SceneSampler::add_snapshot(SnapshotArrays s) {
  const film::ParticleArrays p = s.view();
  thickness_.add(film::sample_film_sections(p, frame_, grid_));
  velocity_->add_snapshot(p);
  solid_->add_snapshot(p);
  ring_->add_snapshot(p);
  dispersion_->add_sample(p, film::DispersionSeries::coarse);
  ++snapshots_;
}

void SceneSampler::advance_interval(CentrecScene& scene) {
  // The same step count as scene.advance(turn period / snapshots_per_turn).
  const double dt = scene.simulation().dt();
  const double interval = scene.turn_period() / spec_.snapshots_per_turn;
  const std::int64_t steps = std::llround(interval / dt), batch = scene.steps_per_batch();
  // Samples at whole batches from the interval's start: advance() then makes the batches it
  // would have made in one call (the feeder, the outlet and the controller act per batch).
  const std::int64_t stride =
      batch * std::max<std::int64_t>(1, std::llround(spec_.dispersion_spacing / (static_cast<double>(batch) * dt)));
  std::int64_t done = 0;
  dispersion_->add_sample(take_snapshot(scene.simulation()).view());
  while (done + stride <= steps) {
    scene.advance(static_cast<double>(stride) * dt);
    done += stride;
    dispersion_->add_sample(take_snapshot(scene.simulation()).view());
  }
  if (done < steps) scene.advance(static_cast<double>(steps - done) * dt);
  dispersion_->end_burst();
}

void SceneSampler::sample_turns(CentrecScene& scene, double turns) {
  const int whole = static_cast<int>(std::floor(turns + 1e-9));
  for (int t = 0; t < whole; ++t) {
    for (int k = 0; k < spec_.snapshots_per_turn; ++k) {
      advance_interval(scene);
      add_snapshot(take_snapshot(scene.simulation()));
    }
    end_turn();
  }
}

void SceneSampler::end_turn() {
  velocity_->end_period();
  solid_->end_period();
  ring_->end_period();
  dispersion_->end_period();
  dispersion_->end_burst(film::DispersionSeries::coarse);
  ++turns_;
}

SampledFilm SceneSampler::fields() const {
  SampledFilm f;
  f.turns = turns_;
  f.snapshots = snapshots_;
  if (snapshots_ == 0) return f;
  f.mean_thickness = thickness_.overall();
  const int na = thickness_.axial_sections(), nt = thickness_.tangential_bins();
  const double z0 = grid_.z_min, z1 = grid_.z_max;
  for (int a = 0; a < na; ++a) {
    f.section_z.push_back(z0 + (a + 0.5) * (z1 - z0) / na);
    f.section_thickness.push_back(thickness_.ring(a));
  }
  for (int b = 0; b < nt; ++b) f.bin_theta.push_back((b + 0.5) * 2.0 * M_PI / nt);
  // Zones from the surface velocity over the sampled sections (away from inlet/outlet).
  const int lo = na > 4 ? na / 5 : 0, hi = na > 4 ? na - na / 5 : na;
  f.surface_velocity = thickness_.surface_velocity(lo, hi);
  f.zones = film::detect_zones(f.surface_velocity.data(), f.surface_velocity.size(), spec_.zone_threshold);

  f.arcs = velocity_->config().sections;
  for (std::size_t s = 0; s < f.arcs.size(); ++s) f.velocity_profiles.push_back(velocity_->profile(static_cast<int>(s)));
  for (int k = 0; k < spec_.bins; ++k) f.bin_centre_d.push_back(velocity_->config().bins.centre_d(k));

  // Solid fraction by zone: average the per-tangential-bin profiles of each zone
  // (equal bin angles, so a plain mean); the std is that of the bins' turn-to-turn std.
  f.solid_fraction.assign(2, std::vector<film::ProfileBin>(static_cast<std::size_t>(spec_.bins)));
  for (int zone = 0; zone < 2; ++zone) {
    for (int k = 0; k < spec_.bins; ++k) {
      double sum = 0.0, var = 0.0;
      std::size_t n = 0, samples = 0, periods = 0;
      for (int b = 0; b < nt; ++b) {
        const int z = f.zones.zone_of_bin.empty() ? 0 : f.zones.zone_of_bin[static_cast<std::size_t>(b)];
        if (z != zone) continue;
        const film::ProfileBin pb = solid_->profile(b)[static_cast<std::size_t>(k)];
        if (!(pb.periods > 0) || !std::isfinite(pb.mean)) continue;
        sum += pb.mean;
        var += pb.stddev * pb.stddev;
        samples += pb.samples;
        periods = std::max(periods, pb.periods);
        ++n;
      }
      film::ProfileBin& out = f.solid_fraction[static_cast<std::size_t>(zone)][static_cast<std::size_t>(k)];
      out.mean = n ? sum / n : std::nan("");
      out.stddev = n ? std::sqrt(var / n) : std::nan("");
      out.samples = samples;
      out.periods = periods;
    }
  }
  f.dispersion = dispersion_->result();
  f.dispersion_lags = dispersion_->lags();
  f.dispersion_z_min = std::max(0.0, dispersion_->config().z_min);
  f.dispersion_z_max = std::min(frame_.length, dispersion_->config().z_max);
  f.dispersion_crossing_fraction = dispersion_->config().crossing_fraction;
  for (int a = 0; a < ring_->config().sections; ++a) {
    f.ring_z.push_back(ring_->section_centre(a));
    f.ring_solid_fraction.push_back(ring_->solid_fraction(a));
    f.ring_volume_flux.push_back(ring_->volume_flux(a));
  }
  return f;
}

std::vector<double> SceneSampler::save() const {
  film::PackedState out;
  out.put(static_cast<double>(turns_));
  out.put(static_cast<double>(snapshots_));
  thickness_.save(out);
  velocity_->save(out);
  solid_->save(out);
  dispersion_->save(out);
  ring_->save(out);
  return out.data;
}

void SceneSampler::load(const std::vector<double>& state) {
  film::StateReader in(state, "scene sampler");
  turns_ = in.count();
  snapshots_ = in.count();
  thickness_.load(in);
  velocity_->load(in);
  solid_->load(in);
  dispersion_->load(in);
  ring_->load(in);
  in.finish();
}

}  // namespace centrec::dem::scene
