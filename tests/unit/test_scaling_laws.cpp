// Paper eqs. (1)-(3) against the paper's own Table 2 (D12 -> D17, D25).
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/scaling_laws.hpp"

using namespace centrec::coupling;

TEST(ScalingLaws, ReproducesPaperTable2) {
  ReceiverOperatingPoint d12{0.12, 0.171, rpm_to_rad_per_s(160.08), 35.7e-3};
  struct Row { double D, L, rpm, mdot; } rows[] = {{0.17, 0.242, 134.50, 50.58e-3}, {0.25, 0.356, 110.91, 74.38e-3}};
  for (const auto& row : rows) {
    auto s = scale_to_diameter(d12, row.D);
    // Table 2 rounds to 3-4 significant digits: 0.2 % tolerance.
    EXPECT_NEAR(s.length / row.L, 1.0, 2e-3) << row.D;
    EXPECT_NEAR(rad_per_s_to_rpm(s.omega) / row.rpm, 1.0, 2e-3) << row.D;
    EXPECT_NEAR(s.mass_flow / row.mdot, 1.0, 2e-3) << row.D;
    std::printf("D=%.2f m: L=%.4f m (paper %.3f), %.2f rpm (paper %.2f), mdot=%.2f g/s (paper %.2f)\n", row.D,
                s.length, row.L, rad_per_s_to_rpm(s.omega), row.rpm, s.mass_flow * 1e3, row.mdot * 1e3);
  }
}

TEST(ScalingLaws, ScalingTwiceEqualsScalingOnce) {
  ReceiverOperatingPoint act{1.5, 2.1, rpm_to_rad_per_s(45.0), 2.0};
  auto once = scale_to_diameter(act, 0.06);
  auto twice = scale_to_diameter(scale_to_diameter(act, 0.3), 0.06);
  EXPECT_NEAR(twice.omega, once.omega, 1e-12 * once.omega);
  EXPECT_NEAR(twice.mass_flow, once.mass_flow, 1e-12 * once.mass_flow);
  EXPECT_NEAR(twice.length, once.length, 1e-12 * once.length);
  // The invariants themselves.
  EXPECT_NEAR(once.omega * once.omega * once.diameter, act.omega * act.omega * act.diameter, 1e-9);
  EXPECT_NEAR(once.mass_flow / once.diameter, act.mass_flow / act.diameter, 1e-12);
}

TEST(ScalingLaws, RejectsNonPositiveDiameter) {
  ReceiverOperatingPoint act{1.5, 2.1, 5.0, 2.0};
  EXPECT_THROW(scale_to_diameter(act, 0.0), std::invalid_argument);
}
