#pragma once
// Particles heated along their own DEM paths (docs/particle_paths.md): an independent check
// of the continuum film's mixing, which the thermal model represents by a gradient
// diffusion (k_mix from the measured dispersion) while the tracked particles carry it as
// they move. Each complete path of a fed drum (dem/film/particle_tracks.hpp) is mapped to
// the receiver (z and time stretched by L_receiver / L_drum: velocities and depths in d
// carry over, docs/scaling.md) and its particle exchanges heat with the continuum solution
// where it is,
//
//     dT_p/dt = (T_film(z_p, eta_p) - T_p) / tau,   tau = rho_s c_p(T_p) d^2 / (12 k_c),
//
// the relaxation time of a sphere conducting into a medium of conductivity k_c
// (Q = 2 pi k_c d (T_film - T_p)); k_c = k_bed + k_rad at its place, without the mixing
// part, which the path itself carries. Above the film's top (eta > t(z): in flight over the
// film) a particle exchanges nothing. Between snapshots T_film and tau are linear in time and
// the equation is integrated exactly. tau = 0 (relax = false) reads the field at every point.
#include <vector>

#include "dem/film/particle_tracks.hpp"
#include "thermal/heat_capacity.hpp"
#include "thermal/material.hpp"

namespace centrec::coupling {

// The steady thermal solution on its (z, xi = eta / t) grid, receiver frame.
struct FilmTemperatureField {
  double length = 0.0;            // m
  std::vector<double> z;          // m, cell centres (uniform spacing length / nz) [nz]
  std::vector<double> thickness;  // m, t(z) at the centres [nz]
  int nxi = 0;
  std::vector<double> T;             // K [nz * nxi], row = z
  std::vector<double> k_conduction;  // W/(m K), k_bed + k_rad [nz * nxi]
  // T and k_c at (z, eta); false above the film's top (eta > t(z)). z is clamped to the
  // grid's ends, eta below the first cell centre reads the first cell.
  bool at(double z, double eta, double& T_out, double& k_out) const;
};

struct PathHeatingSpec {
  double drum_radius = 0.0;    // m, the DEM drum's (eta = R - r)
  double scale = 1.0;          // L_receiver / L_drum: z and time in the receiver
  double T_in = 0.0;           // K, every fed particle's temperature
  thermal::Material material;  // rho_s, d
  thermal::HeatCapacity heat;
  bool relax = true;  // false: tau = 0, T_p = T_film at every point
};

struct HeatedPath {
  double residence = 0.0;  // s, in the receiver
  double T_out = 0.0;      // K, at the last point before it left
  double T_peak = 0.0;     // K, its highest temperature on the way
  double weight = 1.0;     // the residence-time weight (film::ResidenceTimes)
};

// The complete paths heated, one per path with weight > 0; `weights` are
// film::ResidenceTimes::weight (one per path).
std::vector<HeatedPath> heat_paths(const std::vector<film::ParticlePath>& paths, const std::vector<double>& weights,
                                   const std::vector<film::TrackSnapshot>& tracks, const FilmTemperatureField& field,
                                   const PathHeatingSpec& spec);

}  // namespace centrec::coupling
