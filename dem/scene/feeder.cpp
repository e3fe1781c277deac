#include "dem/scene/feeder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "dem/scene/rng_state.hpp"

#include "dem/sphere_mass.hpp"

namespace centrec::dem::scene {

FeederCentreRange feeder_centre_range(const SceneConfig& config, double radius) {
  const FeederSpec& f = config.feeder;
  FeederCentreRange c;
  c.rc = 0.5 * config.drum.diameter - f.radial_offset;
  c.radial_width = f.radial_height - 2.0 * radius > 0 ? f.radial_height - 2.0 * radius : 0.0;
  c.arc_length = f.arc_width - 2.0 * radius;
  c.z0 = f.axial_start + radius;
  c.axial_width = std::max(0.0, f.axial_length - 2.0 * radius);
  return c;
}

Feeder::Feeder(const SceneConfig& config, MaterialId particle_material, std::uint64_t seed)
    : cfg_(config), material_(particle_material), sizes_(config.particle, seed), rng_(seed ^ 0x9e3779b97f4a7c15ULL) {
  next_diameter_ = sizes_.next_diameter();
}

FeederState Feeder::state() const {
  FeederState s;
  s.size_rng = sizes_.rng_state();
  s.place_rng = rng_text(rng_);
  s.backlog = backlog_;
  s.next_diameter = next_diameter_;
  s.stats = stats_;
  return s;
}

void Feeder::restore(const FeederState& s) {
  sizes_.set_rng_state(s.size_rng);
  read_rng_text(s.place_rng, rng_, "feeder");
  backlog_ = s.backlog;
  next_diameter_ = s.next_diameter;
  stats_ = s.stats;
}

double Feeder::feed(Simulation& sim, double elapsed) {
  const FeederSpec& f = cfg_.feeder;
  const double R = 0.5 * cfg_.drum.diameter;
  const double rc = R - f.radial_offset;
  const double dmax = sizes_.max_diameter();
  stats_.requested_mass += f.mass_flow * elapsed;
  backlog_ += f.mass_flow * elapsed;

  // Candidates for overlap: particles near the region (a linear scan once per batch).
  const double r_lo = rc - 0.5 * f.radial_height - dmax, r_hi = rc + 0.5 * f.radial_height + dmax;
  const double z_lo = f.axial_start - dmax, z_hi = f.axial_start + f.axial_length + dmax;
  const double half_arc = 0.5 * f.arc_width / rc + dmax / rc;
  std::vector<Vec3> near;
  std::vector<double> near_r;
  const auto& x = sim.positions();
  const auto& rad = sim.radii();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = std::hypot(x[i].x, x[i].y);
    if (r < r_lo || r > r_hi || x[i].z < z_lo || x[i].z > z_hi) continue;
    const double dth = std::remainder(std::atan2(x[i].y, x[i].x) - f.angle, 2.0 * M_PI);
    if (std::fabs(dth) > half_arc) continue;
    near.push_back(x[i]);
    near_r.push_back(rad[i]);
  }

  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double speed = cfg_.drum.omega * R;  // the wall's linear speed (paper section 4)
  double inserted = 0.0;
  for (;;) {
    const double radius = 0.5 * next_diameter_;
    const double m = sphere_mass(cfg_.particle.material.density, radius);
    if (backlog_ < m) break;
    bool placed = false;
    const FeederCentreRange centres = feeder_centre_range(cfg_, radius);
    for (int a = 0; a < f.max_attempts && !placed; ++a) {
      const double r = rc + (u01(rng_) - 0.5) * centres.radial_width;
      const double th = f.angle + (u01(rng_) - 0.5) * centres.arc_length / rc;
      const double z = centres.z0 + u01(rng_) * centres.axial_width;
      const Vec3 p{r * std::cos(th), r * std::sin(th), z};
      bool free_spot = true;
      for (std::size_t k = 0; k < near.size() && free_spot; ++k) {
        const double s = radius + near_r[k];
        if (norm2(p - near[k]) < s * s) free_spot = false;
      }
      if (!free_spot) continue;
      // Tangential direction of the spin at p: (omega z) x r, normalised.
      const double sgn = cfg_.drum.omega >= 0.0 ? 1.0 : -1.0;
      sim.add_particle({material_, radius, p, Vec3{-std::sin(th), std::cos(th), 0.0} * (sgn * std::fabs(speed))});
      near.push_back(p);
      near_r.push_back(radius);
      placed = true;
    }
    if (!placed) {
      ++stats_.deferred;
      break;  // the region is full: keep the backlog for the next batch
    }
    backlog_ -= m;
    inserted += m;
    stats_.inserted_mass += m;
    ++stats_.inserted;
    next_diameter_ = sizes_.next_diameter();
  }
  return inserted;
}

std::string feeder_shortfall(const SceneConfig& config, const FeederStats& stats, double elapsed) {
  if (stats.requested_mass <= 0.0 || stats.deferred == 0 || stats.inserted_mass >= 0.9 * stats.requested_mass)
    return {};
  const double d = config.particle.diameter;
  char b[512];
  std::snprintf(b, sizeof b,
                "the feeder delivered %.4g g/s of the %.4g g/s asked over the first %.3g s (%lld insertions "
                "deferred: its region is full; its particles leave it at the wall's speed, so it carries about "
                "its radial x axial cross-section times that speed): enlarge dem.feeder.radial_height_d "
                "(now %.3g) and dem.feeder.axial_length_d (now %.3g), or lower the mass flow",
                stats.inserted_mass / elapsed * 1e3, config.feeder.mass_flow * 1e3, elapsed,
                static_cast<long long>(stats.deferred), config.feeder.radial_height / d,
                config.feeder.axial_length / d);
  return b;
}

}  // namespace centrec::dem::scene
