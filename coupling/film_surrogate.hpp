#pragma once
// A film surrogate: the receiver's film as a smooth function of rotation speed and mass
// flow, fitted to the films of an operating map (docs/operating.md). The DEM is isothermal,
// so the film does not depend on the flux or the inlet temperature: one map serves every
// flux.
//
// Each map point's film (a slice's, uniform along z: its first section) is described by its
// thickness t and by u, phi and D at kSurrogateDepths depths s = eta / t in [0, 1]. Each of
// these numbers is fitted by least squares in x = ln(speed), y = ln(mass flow): ln t,
// logit(phi / 0.74048) (so that any fitted value is a solid fraction below the densest
// packing, also off the map's points), and u and D themselves (they reach 0 at the wall or
// the top, where a logarithm fails).
// Two bases, the plane {1, x, y} and the quadric {1, x, y, x^2, xy, y^2}; the quadric only
// with at least 8 points, and each quantity (thickness, u, phi, D profile) takes the basis
// with the smaller leave-one-out error (model no more than the map supports).
#include <string>
#include <vector>

#include "thermal/film_field.hpp"

namespace centrec::coupling {

constexpr int kSurrogateDepths = 25;

// One point of the map: its operating point and its film at the receiver's scale.
struct SurrogateSample {
  double speed_rpm = 0.0;
  double mass_flow = 0.0;  // kg/s
  thermal::FilmField film;
};

enum class SurrogateBasis { plane, quadric };
struct Standardise {  // x = (ln speed - x0) / sx, y = (ln mass flow - y0) / sy
  double x0 = 0.0, sx = 1.0, y0 = 0.0, sy = 1.0;
};
const char* basis_name(SurrogateBasis b);

// Leave-one-out error of one quantity: the point left out predicted by the fit to the rest.
struct SurrogateError {
  std::string quantity, unit;
  SurrogateBasis basis = SurrogateBasis::plane;
  double rms = 0.0, max_abs = 0.0;  // in `unit`
  double range = 0.0;               // the quantity's spread over the map, max - min, in `unit`
};

class FilmSurrogate {
 public:
  // Throws std::invalid_argument with fewer than 3 points, points that do not span both
  // speed and mass flow, films of different geometry, or a film that varies along z.
  explicit FilmSurrogate(std::vector<SurrogateSample> samples);

  // The film at (speed, mass flow): geometry and z sections of the map's first film,
  // thickness and profiles from the fits (u, D >= 0, 0 < phi < 0.74048),
  // mdot and omega set, drum_diameter the map films' (its flow is not imposed: see
  // coupling/film_mass_flow.hpp).
  thermal::FilmField film_at(double speed_rpm, double mass_flow) const;

  // Leave-one-out errors: thickness (in d), surface velocity u(s = 1) (m/s), depth-mean phi
  // and depth-mean D (m2/s). Needs at least 4 points (a plane fit to 3 leaves no check).
  std::vector<SurrogateError> leave_one_out() const;
  // The surrogate fitted without point i (for a derived quantity's leave-one-out, T_out).
  FilmSurrogate without(std::size_t i) const;

  const std::vector<SurrogateSample>& samples() const { return samples_; }
  SurrogateBasis thickness_basis() const { return t_.basis; }

 private:
  struct Fit {  // one coefficient vector per fitted number
    SurrogateBasis basis = SurrogateBasis::plane;
    std::vector<std::vector<double>> coef;
  };
  struct Profiles {  // one map point's numbers
    double log_t = 0.0;
    std::vector<double> u, phi, D;  // kSurrogateDepths each; phi as fitted (logit, film_surrogate.cpp)
  };
  FilmSurrogate(std::vector<SurrogateSample> samples, SurrogateBasis t, SurrogateBasis u, SurrogateBasis phi,
                SurrogateBasis D);
  void fit_all(const SurrogateBasis* forced);

  std::vector<SurrogateSample> samples_;
  std::vector<Profiles> profiles_;
  Standardise st_;
  Fit t_, u_, phi_, D_;
};

// The film's numbers at depths s = eta / t (section 0): what the surrogate fits.
std::vector<double> surrogate_depths();

}  // namespace centrec::coupling
