// Named particles (thermal/particle_data.hpp, docs/particle_data.md):
//   - every property's nominal value lies inside its stated range, every range is proper;
//   - the c_p range is what its source supports: SolarTherm's second CARBO HSP fit (the
//     quadratic in T_C, coded here independently) lies 6.1-8.4 % below the power law over
//     600-900 C, so the range must reach at least that far down and not be more than one
//     point wider;
//   - the heat capacity's scale multiplies c_p and h and inverts exactly (1e-12), and at
//     scale 1 it is bitwise the published power law;
//   - `thermal.particle` sets the material, an explicit material key overrides one value,
//     an unknown name is refused listing the known ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "config/case_thermal.hpp"
#include "tests/test_case_dir.hpp"
#include "thermal/bauxite.hpp"
#include "thermal/particle_data.hpp"

using namespace centrec;
using namespace centrec::thermal;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

TEST(ParticleData, RangesHoldTheirNominalValues) {
  std::set<std::string> names;
  for (const ParticleData& p : particle_table()) {
    EXPECT_TRUE(names.insert(p.name).second) << "duplicate particle " << p.name;
    for (const RangedValue* v : {&p.cp_scale, &p.k_s, &p.alpha, &p.epsilon}) {
      std::printf("%s: %.3g in [%.3g, %.3g] (%s)\n", p.name, v->nominal, v->lo, v->hi, v->source);
      EXPECT_LT(v->lo, v->hi);
      EXPECT_GE(v->nominal, v->lo);
      EXPECT_LE(v->nominal, v->hi);
      EXPECT_GT(std::string(v->source).size(), 5u);
    }
    EXPECT_LE(p.alpha.hi, 1.0);
    EXPECT_LE(p.epsilon.hi, 1.0);
  }
  EXPECT_EQ(std::string(particle_table().front().name), "sg_bauxite");  // the paper's particle is the default
  try {
    particle_data("quartz_sand");
    ADD_FAILURE() << "an unknown particle was accepted";
  } catch (const std::invalid_argument& e) {
    std::printf("error: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("carbo_hsp"), std::string::npos);
  }
}

TEST(ParticleData, CpRangeCoversTheSecondPublishedFit) {
  // SolarTherm CarboHSP_utilities/cp_T.mo: c_p = -1.12e-3 T_C^2 + 2.07 T_C + 264 J/(kg K).
  auto quadratic = [](double T) {
    const double Tc = T - 273.15;
    return -1.12e-3 * Tc * Tc + 2.07 * Tc + 264.0;
  };
  const ParticleData& p = particle_data("carbo_hsp");
  double low = 1.0, high = 0.0;
  for (double Tc = 600.0; Tc <= 900.0; Tc += 1.0) {
    const double r = quadratic(Tc + 273.15) / p.cp.cp(Tc + 273.15);
    low = std::min(low, r);
    high = std::max(high, r);
  }
  std::printf("second fit / power law over 600-900 C: %.4f-%.4f; stated c_p range [%.3f, %.3f]\n", low, high,
              p.cp_scale.lo, p.cp_scale.hi);
  EXPECT_NEAR(low, 0.9162, 5e-4);   // 8.4 % below at 600 C
  EXPECT_NEAR(high, 0.9387, 5e-4);  // 6.1 % below near 750 C
  EXPECT_LE(p.cp_scale.lo, low);
  EXPECT_GE(p.cp_scale.lo, low - 0.01);
}

TEST(ParticleData, HeatCapacityScaleIsExact) {
  HeatCapacity unscaled, scaled;
  scaled.scale = 1.08;
  for (double T : {300.0, 873.15, 1115.0, 1373.15}) {
    EXPECT_EQ(unscaled.cp(T), bauxite_cp(T));  // bitwise: scale 1 changes no arithmetic
    EXPECT_EQ(unscaled.enthalpy(T), bauxite_enthalpy_rise(0.0, T));
    EXPECT_NEAR(scaled.cp(T) / bauxite_cp(T), 1.08, 1e-15);
    EXPECT_NEAR(scaled.enthalpy(T) / bauxite_enthalpy_rise(0.0, T), 1.08, 1e-15);
    const double back = scaled.temperature(scaled.enthalpy(T));
    EXPECT_NEAR(back, T, 1e-12 * T);
  }
  std::printf("scaled c_p(1115 K) = %.2f J/(kg K) = 1.08 x %.2f\n", scaled.cp(1115.0), bauxite_cp(1115.0));
}

TEST(ParticleData, CaseNamesItsParticle) {
  const std::string dir = temp_dir("particle_case");
  const std::string base =
      "film:\n  analytic: {thickness: 6.0e-3, u_surface: 0.26, phi: 0.55, drum_diameter: 1.0, length: 1.0}\n"
      "thermal:\n  grid: {nz: 20, nxi: 8}\n  flux: {q_film: 1.0e5}\n";
  const config::ThermalCase c = config::read_thermal_case(write_case(dir, base + "  particle: carbo_hsp\n"));
  const ParticleData& p = particle_data("carbo_hsp");
  EXPECT_EQ(c.particle, "carbo_hsp");
  EXPECT_EQ(c.model.material.k_s, p.k_s.nominal);
  EXPECT_EQ(c.model.material.alpha, p.alpha.nominal);
  EXPECT_EQ(c.model.material.epsilon, p.epsilon.nominal);
  EXPECT_EQ(c.model.heat.power_law.a, p.cp.a);
  const config::ThermalCase d = config::read_thermal_case(write_case(dir, base));
  EXPECT_EQ(d.particle, "sg_bauxite");
  const config::ThermalCase o =
      config::read_thermal_case(write_case(dir, base + "  particle: carbo_hsp\n  material: {k_s: 3.5}\n"));
  EXPECT_EQ(o.model.material.k_s, 3.5);
  EXPECT_EQ(o.model.material.alpha, p.alpha.nominal);
  try {
    config::read_thermal_case(write_case(dir, base + "  particle: quartz_sand\n"));
    ADD_FAILURE() << "an unknown particle was accepted";
  } catch (const config::ConfigError& e) {
    std::printf("error: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("thermal.particle"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("sg_bauxite"), std::string::npos);
  }
}
