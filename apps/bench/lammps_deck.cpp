#include "bench/lammps_deck.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "bench/deck_state_report.hpp"
#include "dem/material.hpp"
#include "io/atomic_write.hpp"

namespace centrec::bench {
namespace {

void appendf(std::string& s, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void appendf(std::string& s, const char* fmt, ...) {
  char b[2048];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(b, sizeof b, fmt, ap);
  va_end(ap);
  s += b;
}

// LIGGGHTS' normal dashpot 2 sqrt(5/6) |beta| sqrt(2 E* a m*) is sqrt(5) |beta|
// sqrt((4/3) E* a m*), LAMMPS' tsuji form alpha sqrt(k_n m*) with k_n = (4/3) E* a: the
// same law once alpha = sqrt(5) |beta|. (Passing the restitution itself, 0.46, gives
// alpha 0.380 and a head-on restitution of 0.58.)
double lammps_law_alpha(const dem::PairConstants& k) { return std::sqrt(5.0) * std::fabs(k.beta); }

// The contact arguments that give LIGGGHTS' law (docs/dem_physics.md) for a contact of
// effective radius r_star (LIGGGHTS' R*), which LAMMPS forms as r_eff. `scale` = sqrt(R* /
// r_eff) takes LAMMPS' a = sqrt(r_eff delta) back to LIGGGHTS' sqrt(R* delta) wherever a
// coefficient multiplies a.
LammpsLaw::Contact contact_law(const dem::PairConstants& k, double mu, double mu_r, double r_star, double r_eff,
                               double overlap, const dem::PairInteraction& p) {
  LammpsLaw::Contact l;
  const double scale = std::sqrt(r_star / r_eff);
  l.tsuji = lammps_tsuji_parameter(lammps_law_alpha(k));
  l.kt = 8.0 * k.G_eff * scale;
  // LIGGGHTS: gamma_t / gamma_n = sqrt(St / Sn) = sqrt(8 G* / (2 E*)), overlap-free, and
  // LAMMPS' tangential dashpot is xgammat times its normal one.
  l.xgammat = std::sqrt(4.0 * k.G_eff / k.E_eff);
  l.friction = mu;
  // LAMMPS' SDS torque k_roll r_eff^2 theta (+ gamma_roll r_eff^2 theta'), capped at
  // mu_roll r_eff |Fn|. A model LAMMPS has (dem/rolling_models.hpp, RollingModelInfo::lammps:
  // sds) takes its own coefficients, scaled from R* to r_eff; EPSD2 (torque k_t R*^2 theta,
  // k_t = 8 G* sqrt(R* delta), capped at mu_r R* |Fn|) the SDS spring of its k_t at `overlap`.
  const double to_r_eff = (r_star / r_eff) * (r_star / r_eff);
  const dem::RollingModelInfo& model = dem::rolling_model_info(p.rolling_model);
  if (model.lammps) {
    l.k_roll = p.rolling_coefficients[0] * to_r_eff;
    l.gamma_roll = p.rolling_coefficients[1] * to_r_eff;
  } else if (p.rolling_model == dem::RollingModel::epsd2) {
    l.k_roll = 8.0 * k.G_eff * std::sqrt(r_star * overlap) * to_r_eff;
  } else {
    throw std::invalid_argument(std::string("rolling_model: ") + model.name +
                                " - LAMMPS has no such rolling model and no SDS form of it");
  }
  l.rolling_friction = mu_r * r_star / r_eff;
  l.overlap = overlap;
  l.r_eff = r_eff;
  return l;
}

}  // namespace

double lammps_tsuji_alpha(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
         18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

double lammps_tsuji_parameter(double alpha) {
  double lo = 0.0, hi = 1.0;  // alpha(lo) > alpha > alpha(hi)
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (lammps_tsuji_alpha(mid) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

LammpsLaw lammps_law(const FilmCase& c, double pair_overlap_d, double wall_overlap_d) {
  const dem::Material m{c.youngs_modulus, c.poisson_ratio, c.density};
  const dem::PairConstants pp = dem::make_pair_constants(m, m, c.pair_interaction());
  const dem::PairConstants pw = dem::make_pair_constants(m, m, c.wall_interaction());
  LammpsLaw law;
  law.tsuji_alpha = lammps_law_alpha(pp);
  const double r = c.radius();
  law.pair = contact_law(pp, c.friction, c.rolling_friction, 0.5 * r, 0.5 * r, pair_overlap_d * c.diameter,
                         c.pair_interaction());
  law.pair.youngs_modulus = c.youngs_modulus;  // pair style granular mixes E* from E, nu as centrec does
  law.pair.poisson_ratio = c.poisson_ratio;
  // Drum wall: LIGGGHTS' (flat facets) and centrec's R* is r; LAMMPS' cylinder region (side
  // in) reports the curvature radius -2R, so R_eff = r 2R / (2R - r) (0.5 % more). Its
  // hertz/material wall takes E_eff = E / (2 (1 - nu)) (not E* of two bodies), hence the E
  // given below. Both measured with this LAMMPS build (test LammpsDeck.ContactLawMatchesCentrec).
  const double R2 = 2.0 * c.drum_radius;
  const double wall_r_eff = r * R2 / (R2 - r);
  law.wall = contact_law(pw, c.wall_friction, c.wall_rolling_friction, r, wall_r_eff, wall_overlap_d * c.diameter,
                         c.wall_interaction());
  law.wall.poisson_ratio = c.poisson_ratio;
  law.wall.youngs_modulus = 2.0 * (1.0 - c.poisson_ratio) * pw.E_eff * std::sqrt(r / wall_r_eff);
  return law;
}

std::string lammps_contact_commands(const FilmCase& c, const LammpsLaw& law) {
  std::string d;
  const LammpsLaw::Contact& p = law.pair;
  const LammpsLaw::Contact& w = law.wall;
  // Hertz with the Tsuji dashpot, Mindlin with history and its dashpot, SDS rolling (EPSD2's
  // without dashpot: it has none), no twisting (EPSD2 drops the torsion part).
  appendf(d,
          "pair_style granular\n"
          "pair_coeff * * hertz/material %.17g %.17g %.17g damping tsuji tangential mindlin %.17g %.17g %.17g "
          "rolling sds %.17g %.17g %.17g\n",
          p.youngs_modulus, p.tsuji, p.poisson_ratio, p.kt, p.xgammat, p.friction, p.k_roll, p.gamma_roll,
          p.rolling_friction);
  // The drum: a cylinder region rotating about +z at omega; fix wall/gran/region takes the
  // wall velocity at the contact from the region's motion, and the rotation leaves the
  // cylinder in place. The wall rolling sees the particle's absolute spin, as LIGGGHTS'
  // mesh walls (centrec: WallRolling::liggghts).
  appendf(d,
          "variable theta equal %.17g*step*dt\n"
          "region drum cylinder z 0 0 %.17g INF INF side in units box rotate v_theta 0 0 0 0 0 1\n"
          "fix wall all wall/gran/region granular hertz/material %.17g %.17g %.17g damping tsuji tangential mindlin "
          "%.17g %.17g %.17g rolling sds %.17g %.17g %.17g region drum\n",
          c.omega(), c.drum_radius, w.youngs_modulus, w.tsuji, w.poisson_ratio, w.kt, w.xgammat, w.friction, w.k_roll,
          w.gamma_roll, w.rolling_friction);
  return d;
}

void write_lammps_deck(const std::string& path, const FilmCase& c, const FilmState& s, const LammpsDeckSettings& k) {
  std::string d;
  appendf(d, "# centrec benchmark film, generated by centrec_bench_film (apps/bench).\n");
  appendf(d, "# %zu particles, periodic length %.9g m, %d rank(s).\n", s.particles.size(), s.length, k.ranks);
  // Granular essentials: shear history needs newton off and ghost velocities. Split along
  // the drum axis (equal halves of a uniform film, smallest interface), as for LIGGGHTS.
  appendf(d,
          "units si\n"
          "atom_style sphere\n"
          "boundary f f p\n"
          "newton off\n"
          "comm_modify vel yes\n"
          "processors 1 1 *\n"
          "read_data %s\n",
          k.data_file.c_str());
  // Default sorting kept (every 1000 steps); delay 0 with the displacement check = rebuild
  // exactly when needed.
  appendf(d, "neighbor %.9g bin\nneigh_modify delay 0 every 1 check yes\n", k.skin);
  d += lammps_contact_commands(c, lammps_law(c));
  appendf(d,
          "timestep %.17g\n"
          "fix integ all nve/sphere\n"
          "fix grav all gravity %.17g vector 0 %.17g %.17g\n",
          c.dt, c.gravity, c.gravity_y() / c.gravity, c.gravity_z() / c.gravity);
  // The state report's computes ride in the thermo of every run: only the first run may
  // initialise (this LAMMPS re-applies the Tsuji map to the wall's damping at every
  // initialisation, so each later `run` uses `pre no`), and a thermo style cannot change
  // without one. Thermo prints at each run's first and last step only; the last-step cost
  // is charged to LAMMPS' Output timer, which the benchmark takes out of the loop time.
  d += state_report_definitions(c.drum_radius - 0.5 * s.diameter);
  appendf(d,
          "thermo_style custom %s\n"
          "thermo_modify lost error norm no\n"
          "thermo 0\n",
          state_thermo_columns());
  appendf(d, "print \"BENCH_PHASE settle\"\nrun %ld\n", k.settle_steps);
  d += state_print_command("settled");
  for (int r = 0; r < k.repeats; ++r) appendf(d, "print \"BENCH_PHASE timed %d\"\nrun %ld pre no\n", r, k.timed_steps);
  d += state_print_command("final");
  io::write_text_atomically(path, d);
}

}  // namespace centrec::bench
