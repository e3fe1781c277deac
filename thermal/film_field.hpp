#pragma once
// The film field: the one plain data type between the DEM side (via coupling) and the
// thermal model (docs/coupling.md). SI units throughout, no behaviour beyond checks and
// interpolation; the coupling layer fills it, or analytic_film() builds one from YAML.
//
// Layout: axial sections z[i] (i < nz), wall-distance points eta[j] (j < neta, from 0 at
// the wall upward, absolute distances in m), per-section thickness t[i], and per
// (section, point) fields stored row-major as field[i * neta + j]. Values at eta > t[i]
// are ignored. Standard deviations over turns are carried for reporting only.
#include <string>
#include <vector>

namespace centrec::thermal {

struct FilmField {
  std::vector<double> z;     // axial sections, m, strictly increasing (>= 1)
  std::vector<double> eta;   // wall distances, m, strictly increasing, eta[0] = 0
  std::vector<double> t;     // film thickness per section, m (> 0)
  std::vector<double> u;     // axial velocity, m/s            [nz * neta]
  std::vector<double> phi;   // solid volume fraction, -       [nz * neta]
  std::vector<double> D;     // wall-normal dispersion, m2/s   [nz * neta]
  std::vector<double> u_std, phi_std, D_std;  // standard deviations over turns (may be empty)

  // Case metadata (docs/coupling.md).
  double drum_diameter = 0.0;  // m (inner diameter of the rotating cylinder)
  double length = 0.0;         // m (axial length)
  double omega = 0.0;          // rad/s
  double mdot = 0.0;           // kg/s (as simulated)
  double particle_diameter = 0.0;  // m
  std::string scaling;         // description of the scaling applied (free text)

  std::size_t nz() const { return z.size(); }
  std::size_t neta() const { return eta.size(); }

  // Linear interpolation in z (held beyond the ends) of the thickness.
  double thickness(double zq) const;
  // Bilinear interpolation (z, eta) of a [nz*neta] field; eta is clamped to [0, eta.back()].
  double sample(const std::vector<double>& field, double zq, double etaq) const;

  // Throws std::invalid_argument naming the first inconsistency (sizes, ordering, signs).
  void check() const;
};

}  // namespace centrec::thermal
