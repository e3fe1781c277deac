// A tiny case through LIGGGHTS: `centrec dem --engine liggghts` exports,
// runs mpirun -np 1 liggghts and reads the dumps back. The imported holdup (free
// particles) must equal the atom count LIGGGHTS' log reports minus the glued layer, and
// the last dump must hold the same particles. Skipped if LIGGGHTS is not installed
// (./setup.sh installs it).
#include <gtest/gtest.h>

#include "tests/test_case_dir.hpp"

#include <cmath>
#include <filesystem>

#include "config/case_file.hpp"
#include "liggghts/dem_liggghts_run.hpp"
#include "liggghts/liggghts_dump.hpp"
#include "liggghts/liggghts_log_reader.hpp"

using namespace centrec::config;
using namespace centrec::io;
using namespace centrec::liggghts;
namespace fs = std::filesystem;

TEST(LiggghtsEndToEnd, ImportedHoldupEqualsTheLogsAtomCount) {
  LiggghtsLaunch launch;
  if (!liggghts_available(launch.mpirun, launch.liggghts)) GTEST_SKIP() << "mpirun/liggghts not installed";
  const CaseFile cf = read_case_file(std::string(CENTREC_SOURCE_DIR) + "/tests/liggghts/small_drum.yaml");
  const fs::path out = centrec::testing::fresh_dir("e2e");
  const DemRunResult r = run_dem_on_liggghts(cf, *cf.dem, out.string(), launch);

  const LiggghtsLogSummary log = read_liggghts_log((out / "liggghts/log.liggghts").string());
  ASSERT_EQ(log.loops.size(), 2u);
  const long atoms = log.loops.back().atoms;
  std::printf("LIGGGHTS %s: %ld atoms at the end = %lld glued + %lld free imported; holdup %.4g kg\n",
              r.engine_version.c_str(), atoms, static_cast<long long>(r.glued_particles),
              static_cast<long long>(r.free_particles), r.holdup_kg);
  EXPECT_EQ(r.engine, "liggghts");
  EXPECT_NE(r.engine_version.find("3.8"), std::string::npos) << r.engine_version;
  EXPECT_EQ(r.glued_particles + r.free_particles, atoms);
  // The last snapshot (last dump) holds the same free particles.
  ASSERT_FALSE(r.snapshots.empty());
  EXPECT_EQ(static_cast<long long>(r.snapshots.back().data.x.size()), static_cast<long long>(r.free_particles));
  EXPECT_NEAR(r.snapshots.back().data.time, r.simulated_time, 1e-9);
  // Mass balance of the record: nothing lost; the feed near its target. LIGGGHTS rounds a
  // fractional particle count per insertion at random (here ~0.06 per feeder part and
  // insertion), so the count inserted scatters like a Poisson count: tolerance 4 sqrt(N).
  const auto& last = r.mass_flow.back();
  EXPECT_EQ(last.lost, 0.0);
  const double m = 3560.0 * M_PI / 6.0 * std::pow(1.2e-3, 3);  // mean particle mass (5 % uniform spread)
  const double expected = cf.dem->scene.feeder.mass_flow * last.time / m, got = last.fed / m;
  std::printf("fed %.1f particles vs %.1f expected (tolerance 4 sqrt(N) = %.1f), out %.4g kg\n", got, expected,
              4.0 * std::sqrt(expected), last.out);
  EXPECT_NEAR(got, expected, 4.0 * std::sqrt(expected));
  // The sampler saw one turn of snapshots.
  EXPECT_EQ(r.fields.turns, 1u);
  EXPECT_EQ(r.fields.snapshots, 4u);
  fs::remove_all(out);
}
