// View factors of the receiver cavity: summation and reciprocity to 1e-12, the two-disc
// closed form against its tabulated value, and the ring-to-disc factors against an
// independent quadrature of the element-to-disc formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "thermal/cavity_view_factors.hpp"

using namespace centrec::thermal;

namespace {
std::vector<double> uniform_rings(double L, int n) {
  std::vector<double> z(n + 1);
  for (int k = 0; k <= n; ++k) z[k] = L * k / n;
  z[n] = L;
  return z;
}

// Worst |sum_j F_ij - 1| and worst |A_i F_ij - A_j F_ji| / A_i.
void check_enclosure(const CavityViewFactors& v, const char* label) {
  double worst_sum = 0.0, worst_rec = 0.0, min_F = 0.0;
  for (int i = 0; i < v.size(); ++i) {
    double s = 0.0;
    for (int j = 0; j < v.size(); ++j) {
      s += v.F(i, j);
      min_F = std::min(min_F, v.F(i, j));
      worst_rec = std::max(worst_rec, std::abs(v.area[i] * v.F(i, j) - v.area[j] * v.F(j, i)) / v.area[i]);
    }
    worst_sum = std::max(worst_sum, std::abs(s - 1.0));
  }
  std::printf("%s: %d surfaces, max |sum_j F_ij - 1| = %.2e, max reciprocity error %.2e, min F %.2e (tolerance 1e-12)\n",
              label, v.size(), worst_sum, worst_rec, min_F);
  EXPECT_LT(worst_sum, 1e-12);
  EXPECT_LT(worst_rec, 1e-12);
  EXPECT_GE(min_F, -1e-13);  // no negative factor beyond round-off
}
}  // namespace

TEST(CavityViewFactors, SummationAndReciprocity) {
  check_enclosure(cavity_view_factors(0.5, uniform_rings(1.0, 50), 0.5), "1 m x 1 m, open end, 50 rings");
  check_enclosure(cavity_view_factors(0.5, uniform_rings(1.425, 200), 0.3), "1 m x 1.425 m, aperture 0.6 m, 200 rings");
  check_enclosure(cavity_view_factors(0.06, {0.0, 0.001, 0.05, 0.171}, 0.02), "0.12 m, uneven rings, aperture 0.04 m");
}

TEST(CavityViewFactors, CoaxialDiscsMatchTabulatedValues) {
  // Equal discs with r = h: F = (3 - sqrt 5) / 2 = 0.381966 (Howell C-41; Incropera's chart
  // of coaxial parallel discs reads 0.38 at r_j/L = r_i/L = 1).
  const double F11 = disc_to_disc_view_factor(1.0, 1.0, 1.0);
  // r1 = 0.5, r2 = 1, h = 1: X = 1 + 2/0.25 = 9, F = (9 - sqrt(81 - 16)) / 2 = 0.468871.
  const double F2 = disc_to_disc_view_factor(0.5, 1.0, 1.0);
  // A small disc far away: F -> r2^2 / h^2 for r1 -> 0 (point to disc: r2^2 / (h^2 + r2^2)).
  const double Fpt = disc_to_disc_view_factor(1e-4, 1.0, 2.0);
  std::printf("discs r=h: F = %.9f (exact %.9f); r1=0.5, r2=1, h=1: F = %.9f (exact %.9f); point to disc: %.9f (exact %.9f)\n",
              F11, (3 - std::sqrt(5.0)) / 2, F2, (9 - std::sqrt(65.0)) / 2, Fpt, 1.0 / 5.0);
  EXPECT_NEAR(F11, (3 - std::sqrt(5.0)) / 2, 1e-14);
  EXPECT_NEAR(F2, (9 - std::sqrt(65.0)) / 2, 1e-14);
  EXPECT_NEAR(Fpt, 0.2, 1e-8);
  EXPECT_NEAR(disc_to_disc_view_factor(1.0, 1.0, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(disc_to_disc_view_factor(1.0, 0.5, 0.0), 0.25, 1e-15);
}

TEST(CavityViewFactors, RingToDiscMatchesQuadratureOfElementFormula) {
  // F(ring [a, b] -> back disc) = (1 / (b - a)) * integral_a^b F(dA(z) -> disc) dz with the
  // element-to-end-disc closed form (a formula independent of the disc-to-disc algebra),
  // by composite Simpson with 2000 panels.
  const double R = 0.5, L = 1.2;
  const CavityViewFactors v = cavity_view_factors(R, uniform_rings(L, 12), R);
  double worst = 0.0;
  for (int i : {0, 1, 5, 11}) {
    const double a = L * i / 12, b = L * (i + 1) / 12;
    const int n = 2000;
    double s = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      s += w * ring_element_to_end_disc(R, a + (b - a) * k / n);
    }
    const double quad = s * (b - a) / (3.0 * n) / (b - a);
    // The same ring to the front (aperture = whole end) by the mirror image.
    double s2 = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      s2 += w * ring_element_to_end_disc(R, L - (a + (b - a) * k / n));
    }
    const double quad2 = s2 / (3.0 * n);
    const double Fb = v.F(i, v.back()), Fa = v.F(i, v.aperture());
    std::printf("ring %2d [%.2f, %.2f]: F to back %.10f (quadrature %.10f), to aperture %.10f (quadrature %.10f)\n", i, a, b,
                Fb, quad, Fa, quad2);
    worst = std::max({worst, std::abs(Fb - quad), std::abs(Fa - quad2)});
  }
  std::printf("worst difference %.2e (tolerance 1e-9)\n", worst);
  EXPECT_LT(worst, 1e-9);
  // Ring to the next ring for a short drum: an infinitely long limit check. For rings of
  // length l -> 0 the self factor tends to 0 (a thin band sees the rest of the cylinder).
  const CavityViewFactors thin = cavity_view_factors(1.0, {0.0, 1e-6, 2.0}, 1.0);
  std::printf("thin ring self factor %.3e (expected ~ l / (2 R) = 5e-7)\n", thin.F(0, 0));
  EXPECT_LT(thin.F(0, 0), 1e-6);
  EXPECT_GT(thin.F(0, 0), 0.0);
}

TEST(CavityViewFactors, RingToFrontPlateMatchesQuadratureOfElementFormula) {
  // The front plate r_a..R at z = L: F(ring [a, b] -> plate) = (1 / (b - a)) * integral of
  // [F(dA(z) -> disc R) - F(dA(z) -> disc r_a)] dz at distance L - z, with the element-to-
  // coaxial-disc closed form (independent of the disc-to-disc algebra), composite Simpson with
  // 2000 panels; the aperture the same with the disc r_a alone. Two plates: r_a / R = 0.5
  // (1 m drum, 0.5 m aperture) and 0.83 (the D12's 0.12 m drum with a 0.1 m aperture).
  struct Case {
    double R, L, ra;
    int rings;
  };
  double worst = 0.0;
  for (const Case& c : {Case{0.5, 1.0, 0.25, 10}, Case{0.06, 0.171, 0.05, 9}}) {
    const CavityViewFactors v = cavity_view_factors(c.R, uniform_rings(c.L, c.rings), c.ra);
    ASSERT_GE(v.annulus(), 0);
    for (int i : {0, c.rings / 2, c.rings - 1}) {
      const double a = c.L * i / c.rings, b = c.L * (i + 1) / c.rings;
      const int n = 2000;
      double plate = 0.0, aperture = 0.0;
      for (int k = 0; k <= n; ++k) {
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0), h = c.L - (a + (b - a) * k / n);
        const double to_ra = ring_element_to_coaxial_disc(c.R, c.ra, h);
        plate += w * (ring_element_to_end_disc(c.R, h) - to_ra);  // the whole end disc: finite at h = 0
        aperture += w * to_ra;
      }
      plate /= 3.0 * n;
      aperture /= 3.0 * n;
      const double Fp = v.F(i, v.annulus()), Fa = v.F(i, v.aperture());
      std::printf("R %.2f m, r_a %.3f m, ring %d [%.3f, %.3f]: F to plate %.10f (quadrature %.10f), to aperture %.10f "
                  "(quadrature %.10f)\n", c.R, c.ra, i, a, b, Fp, plate, Fa, aperture);
      ASSERT_TRUE(std::isfinite(plate) && std::isfinite(aperture));
      worst = std::max({worst, std::abs(Fp - plate), std::abs(Fa - aperture)});
    }
    // The plate and the aperture are coplanar: they do not see each other; the plate's row
    // sums to one (back plate, rings, aperture 0) and reciprocity holds.
    const int A = v.annulus(), P = v.aperture(), B = v.back();
    EXPECT_EQ(v.F(A, P), 0.0);
    EXPECT_EQ(v.F(A, A), 0.0);
    double row = 0.0;
    for (int j = 0; j < v.size(); ++j) row += v.F(A, j);
    EXPECT_NEAR(row, 1.0, 1e-13);
    EXPECT_NEAR(v.area[A] * v.F(A, B), v.area[B] * v.F(B, A), 1e-15 * v.area[B]);
    // Plate to back plate, independently: (pi R^2 f(R, R, L) - pi r_a^2 f(r_a, R, L)) / A_plate.
    const double pi = 3.14159265358979323846;
    const double plate_back = (pi * c.R * c.R * disc_to_disc_view_factor(c.R, c.R, c.L) -
                               pi * c.ra * c.ra * disc_to_disc_view_factor(c.ra, c.R, c.L)) /
                              (pi * (c.R * c.R - c.ra * c.ra));
    std::printf("  plate to back plate %.12f (disc algebra %.12f), plate row sum - 1 = %.1e\n", v.F(A, B), plate_back, row - 1);
    EXPECT_NEAR(v.F(A, B), plate_back, 1e-13);
  }
  // Limit: the element formula at r = R is the end-disc formula.
  EXPECT_NEAR(ring_element_to_coaxial_disc(0.5, 0.5, 0.3), ring_element_to_end_disc(0.5, 0.3), 1e-15);
  std::printf("worst difference %.2e (tolerance 1e-9)\n", worst);
  EXPECT_LT(worst, 1e-9);
}
