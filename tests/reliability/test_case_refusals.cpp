// Case files that yaml-cpp accepts but that are wrong are refused with the line and key
// (docs/reliability.md): duplicate keys, unterminated quotes, empty values, non-finite
// numbers, integers beyond their range, invalid UTF-8, a misspelt section; and the reader
// makes every check the DEM run makes before it starts, so `validate` refuses what `dem`
// and `run` refuse.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "config/case_thermal.hpp"
#include "dem/scene/centrec_scene.hpp"
#include "dem/scene/packed_film.hpp"
#include "dem/scene/scene_config.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "tests/test_case_dir.hpp"
#include "thermal/analytic_film.hpp"

using namespace centrec;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

namespace {

// The quickstart's drum, small enough to check quickly.
const char* kDem = R"(dem:
  drum: {diameter: 0.03, length: 0.04275, tilt_deg: 45, speed_rpm: 320.16}
  feeder: {mass_flow: 8.925e-3, radial_offset_d: 10}
  run: {duration: 1.5, dt: 2.0e-5}
  sampling: {turns: 3}
)";

// The error reading `text` as a case file ("" = accepted).
std::string error_of(const std::string& text) {
  const std::string dir = temp_dir("refusals");
  try {
    config::read_case_file(write_case(dir, text));
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

// `text` with the first `from` replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << "message: " << (msg)

}  // namespace

TEST(CaseRefusals, TheBaseCaseIsValid) { EXPECT_EQ(error_of(kDem), ""); }

TEST(CaseRefusals, DuplicateKeysNameTheLine) {
  const std::string inline_dup = error_of(with(kDem, "diameter: 0.03,", "diameter: 0.03, diameter: 7.0,"));
  EXPECT_HAS(inline_dup, "case.yaml:2: dem.drum.diameter is given twice");
  const std::string block_dup = error_of(std::string(kDem) + "dem:\n  drum: {diameter: 0.5}\n");
  EXPECT_HAS(block_dup, "case.yaml:6: dem is given twice");
}

TEST(CaseRefusals, AnUnterminatedQuoteIsRefused) {
  const std::string msg = error_of("title: \"quickstart\n" + std::string(kDem));
  EXPECT_HAS(msg, "case.yaml:1: title: the quoted value has no closing \"");
  EXPECT_HAS(error_of("title: 'it''s\n" + std::string(kDem)), "case.yaml:1: title");
  EXPECT_EQ(error_of("title: 'it''s'\n" + std::string(kDem)), "");
}

TEST(CaseRefusals, AnEmptyValueIsNotTheDefault) {
  EXPECT_HAS(error_of(with(kDem, "diameter: 0.03", "diameter: ")), "case.yaml:2: dem.drum.diameter has no value");
  EXPECT_HAS(error_of("dem:\n  drum: null\n"), "case.yaml:2: dem.drum has no value");
  EXPECT_HAS(error_of("dem:\n  drum: ~\n"), "dem.drum has no value");
  EXPECT_HAS(error_of("dem:\n  run: {duration: 1, dt: }\n"), "dem.run.dt has no value");
}

TEST(CaseRefusals, NonFiniteNumbersAreRefused) {
  for (const char* v : {"nan", "inf", "-inf", "1e400"})
    EXPECT_HAS(error_of(with(kDem, "dt: 2.0e-5", std::string("dt: ") + v)), "dem.run.dt = '" + std::string(v) + "' is not a finite number");
  EXPECT_HAS(error_of(with(kDem, "dt: 2.0e-5", "dt: .nan")), "is not a number");
}

TEST(CaseRefusals, IntegersBeyondTheirRangeSayWhatWasGiven) {
  for (const char* v : {"1e300", "-1e300", "9223372036854775808"}) {
    const std::string msg = error_of(std::string(kDem) + "  seed: " + v + "\n");
    EXPECT_HAS(msg, std::string("dem.seed = ") + v + " is out of the allowed range [0, 2147483647]");
    EXPECT_EQ(msg.find("-9223372036854775808"), std::string::npos) << msg;
  }
  EXPECT_HAS(error_of(std::string(kDem) + "  seed: inf\n"), "not a finite number");
}

TEST(CaseRefusals, InvalidUtf8NamesTheLine) {
  const std::string msg = error_of("title: caf\xe9\n" + std::string(kDem));
  EXPECT_HAS(msg, "case.yaml:1: the file is not valid UTF-8");
  EXPECT_EQ(error_of("title: caf\xc3\xa9\n" + std::string(kDem)), "");
}

TEST(CaseRefusals, AMisspeltSectionIsAnUnknownKeyWithTheRightList) {
  const std::string upper = error_of(with(kDem, "dem:", "DEM:") + "receiver: {diameter: 0.12, length: 0.171, "
                                                                 "speed_rpm: 160.08, mass_flow: 0.0357}\n");
  EXPECT_HAS(upper, "case.yaml:1: unknown key 'DEM' (did you mean 'dem'?)");
  const std::string thermall = error_of(std::string(kDem) + "thermall:\n  T_in: 900\n");
  EXPECT_HAS(thermall, "unknown key 'thermall' (did you mean 'thermal'?)");
  EXPECT_HAS(thermall, "known keys here: title, description, dem, receiver, film, thermal, sweep");
  // Nested keys: each known key once, and a suggestion.
  const std::string nested = error_of(with(kDem, "tilt_deg: 45", "tilt: 45"));
  EXPECT_HAS(nested, "unknown key 'dem.drum.tilt' (did you mean 'tilt_deg'?)");
}

TEST(CaseRefusals, ValidateMakesTheChecksTheRunMakes) {
  // Each was accepted by the reader and refused only by the run (or never).
  EXPECT_HAS(error_of(with(kDem, "dt: 2.0e-5", "dt: 1e300")), "case.yaml:4: dem.run.dt: dt = 1e+300 s exceeds the stability bound");
  EXPECT_HAS(error_of(with(kDem, "dt: 2.0e-5", "dt: 2.0e-4")), "exceeds the stability bound 3.237e-05 s");
  EXPECT_HAS(error_of(with(kDem, "diameter: 0.03", "diameter: 1e-300")), "must exceed 20 particle diameters");
  EXPECT_HAS(error_of(with(kDem, "speed_rpm: 320.16", "speed_rpm: 1e300")), "dem.drum.speed_rpm = 1e+300 is out of the allowed range");
  EXPECT_HAS(error_of(with(kDem, "speed_rpm: 320.16", "speed_rpm: 0")), "must be non-zero");
  // A step count that cannot finish (the hang of dt 1e-300).
  EXPECT_HAS(error_of(with(kDem, "dt: 2.0e-5", "dt: 1e-300")), "time steps");
  EXPECT_HAS(error_of(with(kDem, "duration: 1.5", "duration: 1e9")), "cannot finish");
  // A spin-up shorter than one time step runs no step: no spin-up at all.
  const std::string blink = error_of(with(kDem, "duration: 1.5", "duration: 1e-300"));
  EXPECT_HAS(blink, "dem.run.duration");
  EXPECT_HAS(blink, "shorter than one time step");
  EXPECT_EQ(error_of(with(kDem, "duration: 1.5", "duration: 2.0e-5")), "");
  // The longest extension counts in the step guard (a slice that never reaches its flow
  // target would extend its spin-up for years).
  const std::string endless = error_of(with(kDem, "dt: 2.0e-5}", "dt: 2.0e-5, max_extension: 1e12}"));
  EXPECT_HAS(endless, "dem.run.max_extension");
  EXPECT_HAS(endless, "cannot finish");
  // A feed the feeder region cannot insert.
  EXPECT_HAS(error_of(with(kDem, "mass_flow: 8.925e-3", "mass_flow: 1e300")), "dem.feeder.mass_flow: the feed 1e+300 kg/s exceeds what the feeder region can insert");
  EXPECT_HAS(error_of(std::string(kDem) + "  initial_film: {particles: 100000000}\n"), "do not fit in the drum");
}

// What the scene cannot build is refused by the reader with the key named (each was accepted
// by `validate`, then failed in the run without naming it, or ran as nonsense).
TEST(CaseRefusals, ValidateRefusesWhatTheSceneCannotBuild) {
  EXPECT_HAS(error_of(std::string(kDem) + "  gravity: 0\n"), "dem.gravity = 0 is out of the allowed range");
  // The feeder region inside the wall (rough wall included), short of the axis, its arc
  // shorter than the circumference (the drum's radius is 12.5 d, the feeder's centre 2.5 d
  // from the axis).
  EXPECT_HAS(error_of(with(kDem, "radial_offset_d: 10", "radial_offset_d: 10, radial_height_d: 6")),
             "dem.feeder.radial_height_d: the feeder region (0.0072 m high about 0.003 m from the axis) crosses");
  EXPECT_HAS(error_of(with(kDem, "radial_offset_d: 10", "radial_offset_d: 2, radial_height_d: 4.5")),
             "dem.feeder.radial_height_d: the feeder region reaches");
  EXPECT_EQ(error_of(with(kDem, "radial_offset_d: 10", "radial_offset_d: 2, radial_height_d: 2")), "");
  EXPECT_HAS(error_of(with(kDem, "radial_offset_d: 10", "radial_offset_d: 10, arc_width_d: 16")),
             "dem.feeder.arc_width_d: the arc 0.0192 m is longer than the circumference");
  EXPECT_EQ(error_of(with(kDem, "radial_offset_d: 10", "radial_offset_d: 10, arc_width_d: 15")), "");
  // The loose film inside the drum's length.
  EXPECT_HAS(error_of(std::string(kDem) + "  initial_film: {particles: 100, axial_from: 0.05}\n"),
             "dem.initial_film.axial_from: the film starts at 0.05 m, past the drum's end");
  EXPECT_HAS(error_of(std::string(kDem) + "  initial_film: {particles: 100, axial_to: 0.05}\n"),
             "dem.initial_film.axial_to: the film ends at 0.05 m, past the drum's end");
  EXPECT_HAS(error_of(std::string(kDem) + "  initial_film: {particles: 100, axial_from: 0.02, axial_to: 0.01}\n"),
             "dem.initial_film.axial_to: the film's end 0.01 m is not past its start");
  EXPECT_HAS(error_of(with(kDem, "sampling:", "slice: {enabled: true, length_d: 9}\n  sampling:") +
                      "  initial_film: {particles: 100, axial_from: 0.01}\n"),
             "dem.initial_film.axial_from: a slice's film fills its whole period");
  // A settled start needs its source run (the run failed as it built the drum).
  EXPECT_HAS(error_of(std::string(kDem) + "  initial_film: {from_run: no_such_run}\n"),
             "dem.initial_film.from_run: no run to start from: ");
}

TEST(CaseRefusals, ASettledStartsSourceThatIsThereIsRead) {
  const std::string dir = temp_dir("from_run_there");
  std::filesystem::create_directories(dir + "/source");
  std::ofstream(dir + "/source/checkpoint.h5") << "its contents are read by the run\n";
  EXPECT_NO_THROW(config::read_case_file(write_case(dir, std::string(kDem) + "  initial_film: {from_run: source}\n")));
}

// The loose film's count is refused exactly where the scene's lattice runs out (the bound
// was the densest packing of the whole drum, 2.6x the lattice's count here, so `validate`
// passed films the run refused).
TEST(CaseRefusals, TheLooseFilmIsRefusedWhereTheSceneRunsOutOfSites) {
  const std::string dir = temp_dir("film_fits");
  const config::CaseFile cf = config::read_case_file(write_case(dir, kDem));
  dem::scene::SceneConfig scene = cf.dem->scene;
  const std::size_t fits = dem::scene::loose_film_capacity(scene, 1000000);
  std::printf("the drum's starting lattice holds %zu particles\n", fits);
  ASSERT_GT(fits, 1000u);
  auto film = [&](std::size_t n) { return std::string(kDem) + "  initial_film: {particles: " + std::to_string(n) + "}\n"; };
  EXPECT_EQ(error_of(film(fits)), "");
  EXPECT_HAS(error_of(film(fits + 1)), "dem.initial_film.particles: " + std::to_string(fits + 1) +
                                            " particles do not fit in the drum (its starting lattice holds at most " +
                                            std::to_string(fits));
  scene.initial_film.particles = static_cast<std::int64_t>(fits);
  EXPECT_NO_THROW(dem::scene::CentrecScene{scene});
  scene.initial_film.particles = static_cast<std::int64_t>(fits + 1);
  EXPECT_THROW(dem::scene::CentrecScene{scene}, std::invalid_argument);
  // A size distribution: the largest sphere drawn sets the pitch, as in the scene, so the
  // count that first overflows depends on the draw; it is found and both sides built.
  scene.particle.distribution = dem::scene::SizeDistribution::uniform;
  scene.particle.relative_spread = 0.1;
  std::size_t n = dem::scene::loose_film_capacity(scene, 0);
  for (;; ++n) {
    scene.initial_film.particles = static_cast<std::int64_t>(n + 1);
    if (dem::scene::loose_film_capacity(scene, n + 1) < n + 1) break;
  }
  std::printf("uniform +-10 %%: the lattice holds %zu of this draw\n", n);
  EXPECT_THROW(dem::scene::CentrecScene{scene}, std::invalid_argument);
  scene.initial_film.particles = static_cast<std::int64_t>(n);
  EXPECT_NO_THROW(dem::scene::CentrecScene{scene});
}

TEST(CaseRefusals, TheTimeStepAdviceMatchesTheEngines) {
  // The engine prints these for the quickstart (Rayleigh time 8.763e-5 s, Hertz 1.619e-4 s).
  const std::string dir = temp_dir("refusals");
  const config::CaseFile cf = config::read_case_file(write_case(dir, kDem));
  const dem::TimeStepAdvice a = config::dem_time_step_advice(*cf.dem);
  EXPECT_NEAR(a.stable_bound, 3.237e-5, 0.001e-5);
  EXPECT_NEAR(a.recommended, 8.763e-6, 0.001e-6);
  const std::string said = config::time_step_statement(a, 2e-5);
  EXPECT_HAS(said, "dt = 2e-05 s from run.dt: within the stability bound 3.237e-05 s");
  // Above the recommended step the statement says what the knob study measured it costs.
  EXPECT_HAS(said, "step error");
  EXPECT_HAS(said, "docs/dem_knobs.md");
  EXPECT_EQ(config::time_step_statement(a, 5e-6).find("step error"), std::string::npos);
}

TEST(CaseRefusals, TheDemOfAReceiverCaseIsTheDerivedDrum) {
  // `centrec dem` and `centrec run` simulate the drum receiver.dem_diameter_d derives.
  const config::CaseFile cf = config::read_case_file(CENTREC_SOURCE_DIR "/cases/receiver_1m.yaml");
  const config::DemCase d = config::effective_dem(*cf.dem, &*cf.receiver, {});
  EXPECT_NEAR(d.scene.drum.diameter, cf.receiver->dem_diameter_d * d.scene.particle.diameter, 1e-12);
  EXPECT_EQ(cf.receiver->dem_diameter_d, 80.0);  // the case derives its DEM at the validity threshold
  EXPECT_NE(d.scene.drum.diameter, cf.dem->scene.drum.diameter);
}

TEST(CaseRefusals, AReceiverCaseReadsBackFromItsResolvedConfiguration) {
  // --threads / --duration rewrite the resolved configuration and read it again, and a
  // checkpoint resumes from it: the drum and flow that receiver.dem_diameter_d derives must
  // not come back as if given (they would clash with it), nor be echoed with the reader's
  // defaults (D12's 0.12 m where the DEM runs 0.096 m).
  const config::CaseFile cf = config::read_case_file(CENTREC_SOURCE_DIR "/cases/quickstart.yaml");
  const YAML::Node resolved = YAML::Load(cf.resolved_yaml);
  for (const char* key : {"diameter", "length", "speed_rpm", "tilt_deg"})
    EXPECT_FALSE(resolved["dem"]["drum"][key].IsDefined()) << "dem.drum." << key << " echoed though derived";
  EXPECT_FALSE(resolved["dem"]["slice"]["target_mass_flow"].IsDefined());
  EXPECT_FALSE(resolved["dem"]["feeder"]["mass_flow"].IsDefined());
  EXPECT_EQ(config::read_case_text(cf.resolved_yaml, cf.path).resolved_yaml, cf.resolved_yaml);

  config::Overrides o;
  o.keys["dem.run.threads"] = "2";
  o.keys["dem.run.duration"] = "0.5";
  config::CaseFile with;
  ASSERT_NO_THROW(with = config::with_overrides(cf, o));
  const YAML::Node run = YAML::Load(with.resolved_yaml)["dem"]["run"];
  EXPECT_EQ(run["threads"].as<int>(), 2);
  EXPECT_DOUBLE_EQ(run["duration"].as<double>(), 0.5);
  const config::DemCase a = config::effective_dem(*cf.dem, &*cf.receiver, {});
  const config::DemCase b = config::effective_dem(*with.dem, &*with.receiver, {});
  EXPECT_EQ(a.scene.drum.diameter, b.scene.drum.diameter);
  EXPECT_EQ(a.scene.drum.omega, b.scene.drum.omega);
  EXPECT_EQ(dem::scene::target_mass_flow(a.scene), dem::scene::target_mass_flow(b.scene));
  std::printf("quickstart with --threads 2 --duration 0.5: DEM drum %.4f m, %.3f rad/s, %.5f kg/s\n",
              b.scene.drum.diameter, b.scene.drum.omega, dem::scene::target_mass_flow(b.scene));
}

TEST(CaseRefusals, AFilmFileWithAbsurdVelocitiesIsRefused) {
  const std::string dir = temp_dir("refusals_film");
  thermal::AnalyticFilm a;
  a.d = 1.2e-3;
  thermal::FilmField f = thermal::analytic_film(a);
  f.u[f.u.size() / 2] = 1e300;
  {
    io::H5File h = io::H5File::create(dir + "/film.h5");
    io::write_film_field(h, f);
    h.commit();
  }
  const std::string msg = error_of("film: {file: " + dir + "/film.h5}\nthermal: {grid: {nz: 10, nxi: 4}}\n");
  EXPECT_HAS(msg, "film.file");
  EXPECT_HAS(msg, "is not that of a particle film");
}

TEST(CaseRefusals, ADirectoryOrMissingFileIsNamed) {
  const std::string dir = temp_dir("refusals_dir");
  try {
    config::read_case_file(dir);
    ADD_FAILURE();
  } catch (const config::ConfigError& e) {
    EXPECT_HAS(std::string(e.what()), "not a case file");
  }
  try {
    config::read_case_file(dir + "/none.yaml");
    ADD_FAILURE();
  } catch (const config::ConfigError& e) {
    EXPECT_HAS(std::string(e.what()), "no such case file");
  }
}

TEST(CaseRefusals, ThermalSetUpChecksAreMadeByTheReader) {
  // The cavity case with an aperture wider than its drum, and a grid no band solver holds:
  // the thermal run refused them only as it set up; now the reader does.
  std::ifstream in(CENTREC_SOURCE_DIR "/cases/thermal_centrec_cavity.yaml");
  const std::string cavity((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_HAS(error_of(with(cavity, "aperture_diameter: 0.7", "aperture_diameter: 5.0")),
             "thermal.radiation.aperture_diameter: exceeds the drum diameter");
  EXPECT_HAS(error_of(with(cavity, "grid: {nz: 200, nxi: 40}", "grid: {nz: 100000, nxi: 2000}")),
             "GB for its band Jacobian");
}

// An inlet temperature the particle's data do not cover (3000 and 4500 K ran as physics).
TEST(CaseRefusals, AnInletTemperatureOutsideTheParticlesDataIsRefused) {
  std::ifstream in(CENTREC_SOURCE_DIR "/cases/thermal_centrec_cavity.yaml");
  const std::string cavity((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* t : {"3000", "4500", "300"})
    EXPECT_HAS(error_of(with(cavity, "T_in: 873.15", std::string("T_in: ") + t)),
               std::string("thermal.T_in: ") + t + " K lies outside the range sg_bauxite's data hold");
  EXPECT_EQ(error_of(with(cavity, "T_in: 873.15", "T_in: 1373.15")), "");
  EXPECT_EQ(error_of(with(cavity, "T_in: 873.15", "T_in: 323.15")), "");
}

// Property values no solid has ran as physics (k_s, c_p or a constant k of 1e-300 / 1e300);
// a thermal-only case is read by the one case reader (`thermal` refused a `description:`
// that `validate` accepted), and a sweep needs a DEM to run its points on.
TEST(CaseRefusals, ThermalPropertiesNoSolidHasAreRefused) {
  std::ifstream in(CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml");
  const std::string uniform((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_HAS(error_of(with(uniform, "thermal:\n", "thermal:\n  material: {k_s: 1e-300}\n")),
             "thermal.material.k_s = 1e-300 is out of the allowed range");
  EXPECT_HAS(error_of(with(uniform, "thermal:\n", "thermal:\n  material: {rho_s: 1e-300}\n")),
             "thermal.material.rho_s = 1e-300 is out of the allowed range");
  EXPECT_HAS(error_of(with(uniform, "thermal:\n", "thermal:\n  heat_capacity: {model: constant, cp: 1e-300}\n")),
             "thermal.heat_capacity.cp = 1e-300 is out of the allowed range");
  EXPECT_HAS(error_of(with(uniform, "thermal:\n", "thermal:\n  conductivity: {model: constant, k: 1e300}\n")),
             "thermal.conductivity.k = 1e+300 is out of the allowed range");
  EXPECT_EQ(error_of(with(uniform, "thermal:\n", "thermal:\n  heat_capacity: {model: constant, cp: 1200}\n")), "");
  const std::string dir = temp_dir("thermal_only");
  const std::string described = write_case(dir, "description: a thermal-only case\n" + uniform);
  EXPECT_NO_THROW(config::read_thermal_case(described));
  EXPECT_HAS(error_of(uniform + "sweep: {speed_rpm: [50, 60], mass_flow: [0.3]}\n"),
             "sweep: grids speed x mass flow through the DEM; this case has no dem: section");
  try {
    config::read_thermal_case(write_case(dir, kDem));
    ADD_FAILURE() << "a DEM-only case was read as a thermal case";
  } catch (const config::ConfigError& e) {
    EXPECT_HAS(std::string(e.what()), "no thermal: or film: section");
  }
}

TEST(CaseRefusals, EverySweepPointIsCheckedAsItsRunWouldBe) {
  // Each sweep point is a `centrec run` with --speed-rpm and --mass-flow: the reader makes
  // that run's checks (config::dem_run_problem) on every point, naming the swept value.
  const std::string sweep = std::string(kDem) + "sweep: {speed_rpm: [320.16], mass_flow: [8.925e-3, MDOT]}\n";
  EXPECT_EQ(error_of(with(sweep, "MDOT", "4e-3")), "");
  const std::string tiny = error_of(with(sweep, "MDOT", "1e-300"));
  EXPECT_HAS(tiny, "sweep.mass_flow");
  EXPECT_HAS(tiny, "1e-300 kg/s");
  EXPECT_HAS(tiny, "less than one particle");
  EXPECT_HAS(error_of(with(sweep, "MDOT", "1e4")), "exceeds what the feeder region can insert");
  const std::string slow = error_of(with(with(sweep, "MDOT", "4e-3"), "speed_rpm: [320.16]", "speed_rpm: [1e-300]"));
  EXPECT_HAS(slow, "sweep.speed_rpm");
  EXPECT_HAS(slow, "cannot finish");
  // The same feed is refused in the DEM section itself, and by `run --mass-flow`.
  EXPECT_HAS(error_of(with(kDem, "mass_flow: 8.925e-3", "mass_flow: 1e-300")),
             "dem.feeder.mass_flow: the feed 1e-300 kg/s delivers less than one particle");
}

// A rolling model's own coefficients are keys beside rolling_model (dem/rolling_models.hpp):
// read with their defaults and ranges for that model, unknown keys for another.
TEST(CaseRefusals, RollingModelCoefficientsAreTheirModelsKeys) {
  const std::string head = "dem:\n  contacts:\n    particle_wall: {rolling_model: ";
  const config::CaseFile given =
      config::read_case_text(head + "sds, rolling_stiffness: 250, rolling_damping: 0.02}\n", "sds.yaml");
  EXPECT_EQ(given.dem->scene.particle_wall.rolling_model, dem::RollingModel::sds);
  EXPECT_EQ(given.dem->scene.particle_wall.rolling_coefficients, (dem::RollingCoefficients{250.0, 0.02}));
  const config::CaseFile defaults = config::read_case_text(head + "sds}\n", "sds.yaml");
  EXPECT_EQ(defaults.dem->scene.particle_wall.rolling_coefficients,
            dem::default_rolling_coefficients(dem::RollingModel::sds));
  for (const std::string& bad : {head + "sds, rolling_stiffness: 0}\n", head + "epsd2, rolling_stiffness: 250}\n",
                                 head + "sds, rolling_damping: -1}\n"}) {
    try {
      config::read_case_text(bad, "bad.yaml");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const config::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what.find("rolling_stiffness") != std::string::npos ||
                  what.find("rolling_damping") != std::string::npos)
          << what;
    }
  }
}

// Geometry that holds no film: a receiver smaller than 20 particle diameters (validate said
// valid; the run spent its DEM, then failed on an empty film without naming a key), and an
// analytic film thicker than its drum's radius (it ran: T_out 874 K, efficiency 0.13).
TEST(CaseRefusals, AFilmThatCannotLineItsDrumIsRefused) {
  std::ifstream in(CENTREC_SOURCE_DIR "/tests/coupling/small_coupled.yaml");
  const std::string coupled((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string tiny = error_of(with(coupled, "receiver: {diameter: 0.12,", "receiver: {diameter: 0.0006,"));
  EXPECT_HAS(tiny, "receiver");
  EXPECT_HAS(tiny, "must exceed 20 particle diameters");
  std::ifstream u(CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml");
  const std::string uniform((std::istreambuf_iterator<char>(u)), std::istreambuf_iterator<char>());
  const std::string thick = error_of(with(uniform, "drum_diameter: 1.0", "drum_diameter: 0.01"));
  EXPECT_HAS(thick, "film.analytic.thickness");
  EXPECT_HAS(thick, "thinner than the drum's radius");
}
