#pragma once
// Net radiation (radiosity) method for a diffuse grey enclosure in one spectral band
// (Siegel & Howell, Thermal Radiation Heat Transfer; Modest, Radiative Heat Transfer,
// "radiative exchange between grey, diffuse surfaces"). The enclosure is a
// CavityViewFactors set; its last surface is the aperture, an opening whose radiosity is
// given (the surroundings: sigma T_env^4 in the thermal band, 0 for diffuse sunlight).
// For every other surface s with reflectance rho_s:
//     J_s = e_s + rho_s (G0_s + H_s),   H_s = sum_j F_sj J_j
// with e_s the emitted flux and G0_s the primary (collimated) irradiation that the surface
// reflects diffusely. The matrix (I - diag(rho) F_ss) is inverted once; each band solve is
// then a matrix-vector product.
#include <vector>

#include "cavity_view_factors.hpp"

namespace centrec::thermal {

struct BandSolution {
  std::vector<double> J;       // radiosity of the non-aperture surfaces, W/m2
  std::vector<double> H;       // diffuse irradiation (from the other surfaces and the aperture), W/m2
  double aperture_out = 0.0;   // power leaving through the aperture, W: sum_s A_s F_s,ap J_s
  double aperture_in = 0.0;    // diffuse power entering through the aperture, W: A_ap J_ap
};

class CavityEnclosure {
 public:
  // reflectance: one value per non-aperture surface (size() - 1 values), in [0, 1).
  CavityEnclosure(CavityViewFactors vf, std::vector<double> reflectance);

  int surfaces() const { return vf_.size() - 1; }  // without the aperture
  const CavityViewFactors& view_factors() const { return vf_; }
  const std::vector<double>& reflectance() const { return rho_; }

  // emitted and primary: per non-aperture surface (W/m2); J_aperture: the opening's radiosity.
  BandSolution solve(const std::vector<double>& emitted, const std::vector<double>& primary, double J_aperture) const;

  // The linear map from emissive powers to irradiation in a band where surface s emits
  // eps_s E_s and the aperture has radiosity E_env: H = M E + m E_env (M row-major n x n).
  // For an isothermal enclosure at E_env, H = E_env (M 1 + m = 1 up to round-off).
  void irradiation_map(const std::vector<double>& emissivity, std::vector<double>& M, std::vector<double>& m) const;

 private:
  CavityViewFactors vf_;
  std::vector<double> rho_;
  std::vector<double> Fss_;      // F among the non-aperture surfaces, row-major n x n
  std::vector<double> Fsp_;      // F from each surface to the aperture
  std::vector<double> inverse_;  // (I - diag(rho) Fss)^-1, row-major n x n
};

// Inverse of a dense row-major n x n matrix (Gauss-Jordan with partial pivoting); throws
// std::runtime_error if singular.
std::vector<double> dense_inverse(std::vector<double> A, int n);

// Apparent (effective) emissivity of an isothermal cavity of wall emissivity eps (all
// surfaces but the aperture), surroundings at 0 K: the power leaving through the aperture
// over A_ap sigma T^4.
double apparent_emissivity(const CavityViewFactors& vf, double eps);

}  // namespace centrec::thermal
