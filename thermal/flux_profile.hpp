#pragma once
// Concentrated solar flux on the film surface along the axis, q(z) in W/m2
// (docs/thermal_model.md): uniform, Gaussian about a centre, or a table (z, q) interpolated
// linearly (held constant beyond its ends). q(z) is the sunlight's first incidence on the
// film, not the flux through the cavity's aperture: a uniform profile may instead be given by
// its mean aperture flux (aperture_mean), which the film operator turns into the film flux
// q = aperture_mean A_aperture / A_film once it knows both areas (docs/cavity_model.md).
// The table is filled by the caller (the CSV reader lives at the program's edge).
#include <string>
#include <vector>

namespace centrec::thermal {

struct FluxProfile {
  enum class Kind { uniform, gaussian, table };
  Kind kind = Kind::uniform;
  double q = 1.0e6;          // uniform value, or Gaussian peak, on the film, W/m2
  // > 0 (uniform profile, cavity model): the mean flux through the aperture, W/m2; q is then
  // derived from it by the film operator.
  double aperture_mean = 0.0;
  double z_center = 0.5;     // Gaussian centre, m
  double sigma = 0.2;        // Gaussian standard deviation, m
  double q_base = 0.0;       // Gaussian background added everywhere, W/m2
  std::vector<double> table_z;  // m, strictly increasing
  std::vector<double> table_q;  // W/m2

  double at(double z) const;
  // Throws std::invalid_argument naming the problem (empty/unsorted table, negative flux).
  void check() const;
};

}  // namespace centrec::thermal
