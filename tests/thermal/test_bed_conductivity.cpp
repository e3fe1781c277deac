// Bed and air conductivity against the values docs/thermal_model.md expects for 1.2 mm
// bauxite (about 0.2 W/(m K) at 25 C and 0.8 at 1000 C for phi ~ 0.5-0.6), and the
// limits the ZBS model must respect.
#include <gtest/gtest.h>

#include <cstdio>

#include "thermal/air_conductivity.hpp"
#include "thermal/bed_conductivity.hpp"

using namespace centrec::thermal;

TEST(AirConductivity, TableValues) {
  // Air at 1 bar: 0.0263 W/(m K) at 300 K, 0.0824 at 1300 K (VDI Heat Atlas tables).
  std::printf("k_air(300 K) = %.4f (table 0.0263), k_air(1300 K) = %.4f (table 0.0824), tol 3%%\n",
              air_conductivity(300.0), air_conductivity(1300.0));
  EXPECT_NEAR(air_conductivity(300.0), 0.0263, 0.03 * 0.0263);
  EXPECT_NEAR(air_conductivity(1300.0), 0.0824, 0.03 * 0.0824);
}

TEST(BedConductivity, ExpectedMagnitudesFor1p2mmBauxite) {
  BedConductivityModel m;  // defaults: k_s = 2, eps = 0.86, d = 1.2 mm
  for (double phi : {0.5, 0.55, 0.6}) {
    const double k25 = m.k_bed(298.15, phi), k1000 = m.k_bed(1273.15, phi);
    std::printf("phi = %.2f: k_bed(25 C) = %.3f W/(m K) (expect ~0.2, accept 0.12-0.30), k_bed(1000 C) = %.3f "
                "(expect ~0.8, accept 0.55-1.1)\n",
                phi, k25, k1000);
    EXPECT_GT(k25, 0.12);
    EXPECT_LT(k25, 0.30);
    EXPECT_GT(k1000, 0.55);
    EXPECT_LT(k1000, 1.1);
  }
}

TEST(BedConductivity, RadiationTermAndLimits) {
  BedConductivityModel m;
  const auto parts = m.evaluate(1273.15, 0.55);
  const double expect_rad = 4.0 * 5.670374419e-8 * 1273.15 * 1273.15 * 1273.15 * 1.2e-3 / (2.0 / 0.86 - 1.0);
  EXPECT_NEAR(parts.k_rad, expect_rad, 1e-12 * expect_rad);
  // Radiation raises the bed conductivity; a more conductive solid raises it; the bed lies
  // between the gas and the solid conductivity.
  BedConductivityModel no_rad = m;
  no_rad.radiation = false;
  EXPECT_GT(m.k_bed(1273.15, 0.55), no_rad.k_bed(1273.15, 0.55) + 0.3 * parts.k_rad);
  BedConductivityModel better = m;
  better.k_s = 20.0;
  EXPECT_GT(better.k_bed(600.0, 0.55), m.k_bed(600.0, 0.55));
  const double k = no_rad.k_bed(600.0, 0.55);
  EXPECT_GT(k, air_conductivity(600.0));
  EXPECT_LT(k, 2.0);
}
