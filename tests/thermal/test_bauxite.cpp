// Bauxite c_p(T) against the values docs/thermal_model.md quotes, and the exact
// enthalpy integral against quadrature.
#include <gtest/gtest.h>

#include "thermal/bauxite.hpp"

using namespace centrec::thermal;

TEST(Bauxite, CpMatchesQuotedValues) {
  const double cp25 = bauxite_cp(298.15), cp900 = bauxite_cp(1173.15);
  std::printf("c_p(25 C) = %.1f J/(kg K) (quoted 863), c_p(900 C) = %.1f (quoted 1319)\n", cp25, cp900);
  EXPECT_NEAR(cp25, 863.0, 2.0);
  EXPECT_NEAR(cp900, 1319.0, 2.0);
}

TEST(Bauxite, EnthalpyRiseIsIntegralOfCp) {
  const double T0 = 323.15, T1 = 1273.15;
  const int n = 20000;
  double sum = 0.0;  // composite Simpson
  const double h = (T1 - T0) / n;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * bauxite_cp(T0 + i * h);
  }
  sum *= h / 3.0;
  EXPECT_NEAR(bauxite_enthalpy_rise(T0, T1) / sum, 1.0, 1e-10);
}
