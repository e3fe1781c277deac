#pragma once
// Optional periodicity along z (the drum axis) for the periodic-slice mode:
// positions are wrapped into [lo, hi) and separations use the minimum image.
namespace centrec::dem {

struct PeriodicZ {
  bool on = false;
  double lo = 0.0, hi = 0.0;

  double length() const { return hi - lo; }
  double wrap(double z) const {
    if (!on) return z;
    const double len = hi - lo;
    while (z >= hi) z -= len;
    while (z < lo) z += len;
    return z;
  }
  // Minimum image of a separation of two wrapped positions (|dz| < length). Symmetric:
  // image(-dz) == -image(dz) exactly, which the bitwise pair symmetry relies on.
  double image(double dz) const {
    if (!on) return dz;
    const double len = hi - lo;
    if (dz > 0.5 * len) return dz - len;
    if (dz < -0.5 * len) return dz + len;
    return dz;
  }
};

}  // namespace centrec::dem
