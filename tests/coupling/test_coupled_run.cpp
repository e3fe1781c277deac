// End-to-end coupled run: tests/coupling/small_coupled.yaml (the D12
// receiver, its DEM drum derived by eqs 1-3 at D/d = 21, a short DEM, scaled back up) gives
// the stored outlet temperature within 1 K; a rerun takes the cached DEM and gives an
// identical result; a thermal-only change reuses the DEM; the outputs carry the film and the
// scaling; the stored film.h5 reruns the thermal part alone with the same answer; mismatched
// particles between DEM and thermal are refused; an earlier DEM-only run of the same inputs
// (--dem-from) gives the same answer, one of other inputs is refused.
#include <gtest/gtest.h>

#include <cstring>

#include "tests/test_case_dir.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <utility>

#include "config/case_file.hpp"
#include "coupling/film_along_drum.hpp"
#include "io/code_version.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "runs/coupled_output.hpp"
#include "runs/coupled_run.hpp"
#include "runs/dem_cache.hpp"
#include "runs/earlier_dem_run.hpp"
#include "runs/provenance.hpp"

using namespace centrec;
using namespace centrec::config;
using namespace centrec::io;
using namespace centrec::runs;
namespace fs = std::filesystem;

namespace {
const std::string kCase = std::string(CENTREC_SOURCE_DIR) + "/tests/coupling/small_coupled.yaml";
// Stored by a run of this test (2D, 60 x 12, van Leer advection; the DEM is deterministic at
// any thread count and, with -ffp-contract=off, in Release and sanitizer builds alike). It
// pins one DEM trajectory, the default mapping (as_measured_carried_flow), the default solar
// depth (each cell's own phi) and the thermal solve of this short, unsteady D/d 21 film, not
// the physics; a change to any of them moves it and must say why.
constexpr double kStoredTout = 1071.19;


// The case with its text edited (thermal-only or particle changes).
CaseFile edited_case(const std::string& dir, const std::string& from, const std::string& to) {
  std::ifstream in(kCase);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, from.size(), to);
  std::ofstream(dir + "/edited.yaml") << text;
  return read_case_file(dir + "/edited.yaml");
}
}  // namespace

TEST(CoupledRun, SmallCaseRegressionCacheAndOutputs) {
  const std::string dir = centrec::testing::temp_dir("coupled");
  RunOptions o;
  o.cache_dir = dir + "/cache";
  o.allow_small_drum = o.allow_unsteady = true;  // D/d 21, 0.2 s: a regression, not a study
  const CaseFile cf = read_case_file(kCase);
  const CoupledRun first = run_coupled_case(cf, o);
  const double T1 = first.result.balance.T_out;
  std::printf("T_out %.3f K (stored %.2f K, tolerance 1 K); DEM %.1f s (run), outlet %.4g g/s; k_eff parts: see "
              "summary\n",
              T1, kStoredTout, first.dem_seconds, first.averages.mdot * 1e3);
  EXPECT_FALSE(first.dem_cached);
  EXPECT_NEAR(T1, kStoredTout, 1.0);
  // The thermal model carries the case's (receiver's) flow, imposed by one factor.
  EXPECT_NEAR(first.result.balance.mass_flow / 0.0357, 1.0, 1e-2);
  EXPECT_EQ(first.imposed.mdot, 0.0357);
  // What was allowed is said: the small drum (and whatever else this short run missed).
  ASSERT_FALSE(first.warnings.empty());
  EXPECT_NE(first.warnings[0].find("D/d = 21"), std::string::npos);
  // The receiver derived the DEM drum by eqs 1-3 and the film was scaled back up.
  EXPECT_NEAR(first.dem.scene.drum.diameter, 21 * 1.2e-3, 1e-12);
  EXPECT_NEAR(first.scale.radius_ratio, 0.12 / 0.0252, 1e-9);
  EXPECT_NEAR(first.thermal.film.length, 0.171, 1e-12);

  const CoupledRun again = run_coupled_case(cf, o);
  std::printf("rerun: cached %d, DEM stage %.3f s, T_out %.6f K\n", again.dem_cached, again.dem_seconds,
              again.result.balance.T_out);
  EXPECT_TRUE(again.dem_cached);
  EXPECT_EQ(again.cache_key, first.cache_key);
  EXPECT_EQ(again.result.balance.T_out, T1);
  EXPECT_EQ(again.thermal.film.u, first.thermal.film.u);
  // The first run handed its film over in memory, the rerun read it from the cached dem.h5:
  // the same numbers to the last bit (NaN marks an empty bin in both).
  auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
  };
  const auto &fa = first.averages, &ca = again.averages;
  EXPECT_EQ(std::memcmp(&fa.mdot, &ca.mdot, sizeof(double)), 0);
  EXPECT_TRUE(same(fa.thickness, ca.thickness) && same(fa.thickness_std, ca.thickness_std));
  EXPECT_EQ(fa.moving_fraction, ca.moving_fraction);
  EXPECT_EQ(fa.steady, ca.steady);
  EXPECT_TRUE(same(fa.phi_glued, ca.phi_glued) && same(fa.dispersion, ca.dispersion));
  ASSERT_EQ(fa.ring_phi.size(), ca.ring_phi.size());
  for (std::size_t k = 0; k < fa.ring_phi.size(); ++k)
    EXPECT_TRUE(same(fa.ring_phi[k], ca.ring_phi[k]) && same(fa.ring_flux[k], ca.ring_flux[k]) &&
                same(fa.ring_flux_std[k], ca.ring_flux_std[k]));

  // A killed DEM stage leaves CACHE/<key>.tmp<pid> with its last checkpoint: the next run of
  // the same inputs takes it over and continues from there (here the checkpoint written at
  // the end of the first run, so the answer must be identical) instead of starting again.
  const pid_t gone = ::fork();
  if (gone == 0) ::_exit(0);
  ::waitpid(gone, nullptr, 0);
  const std::string entry = o.cache_dir + "/" + first.cache_key;
  const std::string killed = entry + ".tmp" + std::to_string(gone);
  fs::rename(entry, killed);
  EXPECT_EQ(interrupted_dem_run(o.cache_dir, first.cache_key), killed);
  const CoupledRun resumed = run_coupled_case(cf, o);
  std::printf("resumed from %s: T_out %.6f K\n", resumed.dem_resumed_from.c_str(), resumed.result.balance.T_out);
  EXPECT_FALSE(resumed.dem_cached);
  EXPECT_EQ(resumed.dem_resumed_from, killed);
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_TRUE(fs::exists(entry + "/dem.h5"));
  EXPECT_EQ(resumed.result.balance.T_out, T1);
  // A folder whose process is alive (this one) is another run's, not an interrupted one.
  fs::copy(entry, entry + ".tmp" + std::to_string(::getpid()), fs::copy_options::recursive);
  EXPECT_EQ(interrupted_dem_run(o.cache_dir, first.cache_key), "");

  // Thermal-only change: same DEM key, different answer.
  const CaseFile hotter = edited_case(dir, "q_film: 2.0e5", "q_film: 3.0e5");
  const CoupledRun h = run_coupled_case(hotter, o);
  std::printf("flux 3e5: cached %d, T_out %.2f K\n", h.dem_cached, h.result.balance.T_out);
  EXPECT_TRUE(h.dem_cached);
  EXPECT_GT(h.result.balance.T_out, T1 + 10.0);

  // Another thread count, in the case or by --threads: the same DEM key (the engine is
  // bitwise the same at any thread count), so the cached DEM serves both.
  const CaseFile more_threads = edited_case(dir, "threads: 1", "threads: 2");
  RunOptions three_threads = o;
  three_threads.overrides.keys["dem.run.threads"] = "3";
  for (const auto& [c, opt] : {std::pair<const CaseFile*, const RunOptions*>{&more_threads, &o}, {&cf, &three_threads}}) {
    const CoupledRun t = run_coupled_case(*c, *opt);
    std::printf("threads %s: cached %d, key %s (first %s)\n", c == &cf ? "--threads 3" : "2 in the case", t.dem_cached,
                t.cache_key.c_str(), first.cache_key.c_str());
    EXPECT_TRUE(t.dem_cached);
    EXPECT_EQ(t.cache_key, first.cache_key);
    EXPECT_EQ(t.result.balance.T_out, T1);
  }

  // An earlier DEM run given by --dem-from (here the cache entry, which holds what
  // `centrec dem` writes): the same answer without DEM work or cache; another thread count is
  // the same DEM; a changed DEM input is refused, naming the key and both values.
  RunOptions given = o;
  given.dem_from = entry;
  given.cache_dir = dir + "/no-cache";
  const CoupledRun g = run_coupled_case(more_threads, given);
  std::printf("from the earlier run %s: T_out %.6f K (coupled %.6f K)\n", g.dem_dir.c_str(), g.result.balance.T_out,
              T1);
  EXPECT_TRUE(g.dem_given);
  EXPECT_EQ(g.result.balance.T_out, T1);
  EXPECT_FALSE(fs::exists(given.cache_dir));
  for (const auto& [from, to, key] : {std::tuple<const char*, const char*, const char*>{"dt: 2.0e-5", "dt: 1.0e-5",
                                                                                          "dem.run.dt: 1e-05 here, 2e-05"},
                                      {"dem_diameter_d: 21", "dem_diameter_d: 22", "receiver.dem_diameter_d: 22 here"}}) {
    try {
      run_coupled_case(edited_case(dir, from, to), given);
      ADD_FAILURE() << "a run of other DEM inputs (" << to << ") was taken";
    } catch (const std::invalid_argument& e) {
      std::printf("%s\n", e.what());
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  given.overrides.keys["dem.seed"] = "7";
  EXPECT_THROW(run_coupled_case(cf, given), std::invalid_argument);

  // Outputs: results.h5 with /film and /coupling, film.h5 reusable, summary figures.
  write_coupled_h5(dir, first, case_provenance(cf.path, cf.resolved_yaml));
  // Provenance in both files: the resolved case, the code version, the case file's hash.
  for (const char* name : {"/results.h5", "/film.h5"}) {
    const auto h5 = io::H5File::open_read(dir + name);
    EXPECT_NE(h5.string_attribute("/", "resolved_config").find("receiver:"), std::string::npos) << name;
    EXPECT_EQ(h5.string_attribute("/", "code_version"), centrec::io::code_version()) << name;
    EXPECT_NE(h5.string_attribute("/", "input_hashes").find("fnv1a64:"), std::string::npos) << name;
  }
  const auto summary = coupled_summary(first);
  EXPECT_EQ(summary["T_out_K"].get<double>(), T1);
  EXPECT_TRUE(summary.contains("scaling"));
  EXPECT_GT(summary["k_eff"]["film_mean"]["k_eff"].get<double>(), 0.0);
  const auto film = io::read_film_field(io::H5File::open_read(dir + "/film.h5"));
  EXPECT_EQ(film.u, first.thermal.film.u);
  const auto res = io::H5File::open_read(dir + "/results.h5");
  EXPECT_TRUE(res.exists("/coupling/flow_closure"));
  EXPECT_EQ(summary["warnings"].size(), first.warnings.size());
  EXPECT_TRUE(res.exists("/steady/T"));
  // The stored film is reusable: a case giving `film: {file: film.h5}` skips the DEM and
  // reproduces the coupled answer.
  const CaseFile reuse = edited_case(dir, "thermal:\n", "film: {file: " + dir + "/film.h5}\nthermal:\n");
  const CoupledRun fr = run_coupled_case(reuse, o);
  std::printf("from film.h5: T_out %.6f K (coupled %.6f K)\n", fr.result.balance.T_out, T1);
  EXPECT_FALSE(fr.film_from_dem());
  EXPECT_NEAR(fr.result.balance.T_out, T1, 1e-9);
  fs::remove_all(dir);
}

// A DEM drum below the scale-down validity threshold is refused before any DEM work, with
// the D/d asked, the threshold and where it was measured; --allow-small-drum runs it.
// The same small drum mapped along_drum (film: {mapping: along_drum}): the thermal film has
// every section past the feeder, each with its own flow; the outputs name the mapping.
TEST(CoupledRun, ADrumsFilmAlongTheDrum) {
  const std::string dir = centrec::testing::temp_dir("coupled_along");
  RunOptions o;
  o.cache_dir = dir + "/cache";
  o.allow_small_drum = o.allow_unsteady = true;
  const CaseFile cf = edited_case(dir, "thermal:\n", "film: {mapping: along_drum}\nthermal:\n");
  ASSERT_EQ(cf.thermal->film_source.mapping, "along_drum");
  const CoupledRun r = run_coupled_case(cf, o);
  const auto sections = centrec::coupling::sections_past_feeder(r.averages);
  const auto& c = r.closure.section_over_measured;
  std::printf("along_drum: %zu of %zu sections (from z = %.4g m, feeder ends at %.4g m); closure per section "
              "%.3f-%.3f; T_out %.2f K; %s\n",
              sections.size(), r.averages.ring_z.size(), r.averages.ring_z[sections.front()], r.averages.feed_end,
              *std::min_element(c.begin(), c.end()), *std::max_element(c.begin(), c.end()), r.result.balance.T_out,
              r.mapping.text.c_str());
  EXPECT_EQ(r.mapping.mapping, "along_drum");
  EXPECT_GT(r.averages.feed_end, 0.0);
  EXPECT_EQ(c.size(), sections.size());
  EXPECT_GT(sections.size(), r.averages.ring_z.size() / 2);  // the feeder is a short region at the back plate
  EXPECT_GT(r.result.balance.T_out, 873.15 + 10.0);
  fs::remove_all(dir);
}

TEST(CoupledRun, SmallDrumIsRefusedUnlessAllowed) {
  const std::string dir = centrec::testing::temp_dir("coupled");
  RunOptions o;
  o.cache_dir = dir + "/cache";
  try {
    run_coupled_case(read_case_file(kCase), o);
    ADD_FAILURE() << "a D/d 21 drum was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    std::printf("%s\n", m.c_str());
    EXPECT_NE(m.find("D/d = 21"), std::string::npos);
    EXPECT_NE(m.find("D/d = 80"), std::string::npos);
    EXPECT_NE(m.find("docs/validity_threshold.md"), std::string::npos);
    EXPECT_NE(m.find("--allow-small-drum"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir + "/cache"));
  fs::remove_all(dir);
}

TEST(CoupledRun, ThermalParticlesMustMatchTheDem) {
  const std::string dir = centrec::testing::temp_dir("coupled");
  // Refused as the case is read (config::coupled_run_problem), so `validate` refuses it too.
  try {
    edited_case(dir, "  T_in: 873.15", "  material: {d: 1.0e-3}\n  T_in: 873.15");
    ADD_FAILURE() << "mismatched particles were accepted";
  } catch (const centrec::config::ConfigError& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("thermal.material.d"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir + "/cache"));  // refused before any DEM work
  fs::remove_all(dir);
}

TEST(CoupledRun, AReceiverThatDoesNotDeriveTheDemIsNotADemInput) {
  // A drum run without a receiver serves a case that only scales its film up (receiver with
  // dem_diameter_d 0); one that derives the DEM drum from the receiver is another DEM.
  const std::string dir = centrec::testing::fresh_dir("dem_from_receiver");
  const std::string dem = "dem:\n  drum: {diameter: 0.096, length: 0.1368, speed_rpm: 178.975}\n  seed: 12345\n";
  std::ofstream(dir + "/dem.h5") << "";
  nlohmann::json summary;
  summary["resolved_config"] = "title: drum\n" + dem;
  std::ofstream(dir + "/summary.json") << summary.dump();
  const std::string receiver = "receiver: {diameter: 0.12, length: 0.171, speed_rpm: 160.08, mass_flow: 0.0357";
  EXPECT_NO_THROW(centrec::runs::earlier_dem_run_summary("title: scaled\n" + receiver + ", dem_diameter_d: 0}\n" + dem, dir));
  try {
    centrec::runs::earlier_dem_run_summary("title: derived\n" + receiver + ", dem_diameter_d: 80}\n" + dem, dir);
    ADD_FAILURE() << "a DEM derived from the receiver was taken for a run without one";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("receiver.dem_diameter_d: 80 here, (absent) in that run"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
