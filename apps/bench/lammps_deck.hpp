#pragma once
// The LAMMPS input for the benchmark film (Debian `lammps`, 29 Sep 2021 update 2, GRANULAR
// package): the closest LAMMPS form of centrec's / LIGGGHTS' contact law
// (docs/dem_physics.md) and the deck (settle, state report, timed runs, final report).
// The data file is LIGGGHTS' (write_liggghts_data): atom_style sphere reads the same
// "id type diameter density x y z" atoms and "id vx vy vz wx wy wz" velocities.
// apps/bench/README.md "LAMMPS settings" gives the reasoning and what cannot be matched.
#include <string>

#include "bench/film_case.hpp"
#include "bench/film_initial_state.hpp"

namespace centrec::bench {

// The arguments of `pair_coeff` and `fix wall/gran/region granular` that reproduce the
// law, each written so that LAMMPS' formula gives LIGGGHTS' value (see lammps_law).
struct LammpsLaw {
  struct Contact {
    double youngs_modulus = 0.0;   // hertz/material E (Pa) as LAMMPS takes it
    double poisson_ratio = 0.0;
    double tsuji = 0.0;            // damping tsuji parameter (not the restitution it yields)
    double kt = 0.0;               // tangential mindlin k_t: F_t = k_t a xi, a = sqrt(R_eff delta)
    double xgammat = 0.0;          // tangential dashpot / normal dashpot
    double friction = 0.0;
    double k_roll = 0.0;           // rolling sds stiffness (constant)
    double gamma_roll = 0.0;       // rolling sds dashpot
    double rolling_friction = 0.0; // rolling sds mu_roll
    double overlap = 0.0;          // m: the overlap at which k_roll equals EPSD2's k_t (R*/R_eff)^2
    double r_eff = 0.0;            // m: LAMMPS' effective radius of the contact
  };
  Contact pair, wall;
  double tsuji_alpha = 0.0;        // normal dashpot / sqrt(m* (4/3) E* a): sqrt(5) |beta| (pair and wall)
};

// Typical overlaps of the settled film, at which LAMMPS' constant rolling stiffness equals
// EPSD2's k_t R*^2 (k_t grows with sqrt(overlap)): (mean of sqrt(overlap))^2 over the
// contacts of the 1e4 film after 2000 steps in LAMMPS (apps/bench/README.md).
constexpr double kLammpsPairOverlapD = 1.5e-3;  // particle-particle, / d
constexpr double kLammpsWallOverlapD = 1.6e-3;  // particle-wall, / d

LammpsLaw lammps_law(const FilmCase& c, double pair_overlap_d = kLammpsPairOverlapD,
                     double wall_overlap_d = kLammpsWallOverlapD);

// LAMMPS' map from the `damping tsuji` parameter to the dashpot factor alpha
// (pair style granular: alpha = 1.2728 - 4.2783 e + ... + 4.8218 e^6), and its inverse on [0, 1]
// (alpha decreases there from 1.2728 to 0.0003; out-of-range alphas give the end points).
double lammps_tsuji_alpha(double e);
double lammps_tsuji_parameter(double alpha);

// pair_style, pair_coeff, the drum as a rotating region and its wall fix: the deck's law,
// also used on its own by the contact-law test.
std::string lammps_contact_commands(const FilmCase& c, const LammpsLaw& law);

struct LammpsDeckSettings {
  std::string data_file;   // written by write_liggghts_data
  int ranks = 1;           // processor grid 1 x 1 x ranks (split along the drum axis)
  double skin = 0.48e-3;   // neighbour skin, m
  long settle_steps = 2000;
  long timed_steps = 1000;
  int repeats = 3;         // consecutive timed runs, each reported as its own "Loop time"
};

void write_lammps_deck(const std::string& path, const FilmCase& c, const FilmState& s, const LammpsDeckSettings& k);

}  // namespace centrec::bench
