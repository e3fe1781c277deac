// Reading LIGGGHTS results back: a dump file the test writes
// (columns in LIGGGHTS' order and shuffled, with an extra column), a truncated dump, the
// dump file naming, and the mass-flow record with its mass balance.
#include <gtest/gtest.h>

#include "tests/test_case_dir.hpp"

#include <filesystem>
#include <fstream>

#include "liggghts/dem_liggghts_run.hpp"
#include "liggghts/liggghts_dump.hpp"

using namespace centrec::liggghts;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

const char* kHeader =
    "ITEM: TIMESTEP\n2343\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS ff ff ff\n"
    "-0.01575 0.01575\n-0.01575 0.01575\n-0.0024 0.0236\n";

}  // namespace

TEST(LiggghtsImport, ReadsADumpIntoParticleColumns) {
  const fs::path d = centrec::testing::fresh_dir("dump");
  write(d / "film_000000002343.dump",
        std::string(kHeader) +
            "ITEM: ATOMS id radius x y z vx vy vz \n"
            "1201 0.0006 0.0131369 -0.00294296 0.00119893 0.0986909 0.440379 0.000351363 \n"
            "1202 0.00055 0.0131295 -0.00294081 0.00241343 0.100765 0.438515 -0.00291195 \n"
            "1500 0.00065 -0.01 0.002 0.011 -1.5 2.5 3.5 \n");
  const auto s = read_liggghts_dump((d / "film_000000002343.dump").string(), 2e-5);
  ASSERT_EQ(s.x.size(), 3u);
  EXPECT_DOUBLE_EQ(s.time, 2343 * 2e-5);
  EXPECT_EQ(s.id[0], 1201);
  EXPECT_EQ(s.id[2], 1500);
  EXPECT_DOUBLE_EQ(s.radius[1], 0.00055);
  EXPECT_DOUBLE_EQ(s.x[2], -0.01);
  EXPECT_DOUBLE_EQ(s.y[2], 0.002);
  EXPECT_DOUBLE_EQ(s.z[2], 0.011);
  EXPECT_DOUBLE_EQ(s.vx[2], -1.5);
  EXPECT_DOUBLE_EQ(s.vy[2], 2.5);
  EXPECT_DOUBLE_EQ(s.vz[2], 3.5);
  EXPECT_DOUBLE_EQ(s.z[0], 0.00119893);

  // Columns are found by name: another order with an extra column gives the same values.
  write(d / "film_000000004686.dump", std::string(kHeader) +
                                          "ITEM: ATOMS vz type x id z y radius vy vx\n"
                                          "3.5 1 -0.01 1500 0.011 0.002 0.00065 2.5 -1.5\n"
                                          "0 1 0 7 0 0 0.0006 0 0\n"
                                          "0 1 0 8 0 0 0.0006 0 0\n");
  const auto t = read_liggghts_dump((d / "film_000000004686.dump").string(), 2e-5);
  EXPECT_EQ(t.id[0], 1500);
  EXPECT_DOUBLE_EQ(t.vx[0], -1.5);
  EXPECT_DOUBLE_EQ(t.radius[0], 0.00065);

  // Listing sorts by timestep (not by name length), and names give their step.
  write(d / "film_0099.dump", std::string(kHeader) + "ITEM: ATOMS id radius x y z vx vy vz\n1 1 1 1 1 1 1 1\n"
                                                     "2 1 1 1 1 1 1 1\n3 1 1 1 1 1 1 1\n");
  const auto files = list_dump_files(d.string(), "film_", ".dump");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(dump_file_step(files[0]), 99);
  EXPECT_EQ(dump_file_step(files[2]), 4686);
  fs::remove_all(d);
}

TEST(LiggghtsImport, RefusesATruncatedOrColumnlessDump) {
  const fs::path d = centrec::testing::fresh_dir("bad_dump");
  write(d / "short.dump", std::string(kHeader) + "ITEM: ATOMS id radius x y z vx vy vz\n1 1 1 1 1 1 1 1\n");
  EXPECT_THROW(read_liggghts_dump((d / "short.dump").string(), 1e-5), std::runtime_error);
  write(d / "nocol.dump", std::string(kHeader) + "ITEM: ATOMS id x y z\n1 1 1 1\n2 2 2 2\n3 3 3 3\n");
  try {
    read_liggghts_dump((d / "nocol.dump").string(), 1e-5);
    FAIL() << "a dump without radius was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
  fs::remove_all(d);
}

TEST(LiggghtsImport, MassFlowRecordAndItsBalance) {
  const fs::path d = centrec::testing::fresh_dir("flow");
  // time fed out holdup particles; the last line is being written (incomplete).
  write(d / "mass_flow.txt",
        "# Fix print output for fix flowlog\n"
        "0.001 0 0 0.01 100\n"
        "0.002 0.0002 0.0001 0.0101 101\n"
        "0.003 0.0004 0.0002 0.0100 100\n"
        "0.004 0.0005");
  const auto log = read_liggghts_mass_flow((d / "mass_flow.txt").string(), 0.01);
  ASSERT_EQ(log.size(), 3u);
  EXPECT_DOUBLE_EQ(log[1].fed, 0.0002);
  EXPECT_EQ(log[1].particles, 101);
  EXPECT_DOUBLE_EQ(log[1].lost, 0.0);  // 0.01 + 0.0002 - 0.0001 - 0.0101 = 0
  // 0.01 + 0.0004 - 0.0002 - 0.0100 = 0.0002 kg unaccounted for: lost through the box.
  EXPECT_NEAR(log[2].lost, 0.0002, 1e-12);
  EXPECT_DOUBLE_EQ(log[2].axial_flow, 0.0);  // a 5-column record (a drum's deck before the slice column)
  // A slice's record carries its axial flow sum(m v_z) / L in a sixth column.
  write(d / "slice_flow.txt", "0.001 0 0 0.01 100 0.0321\n0.002 0 0 0.01 100 0.0298\n");
  const auto slice = read_liggghts_mass_flow((d / "slice_flow.txt").string(), 0.01);
  ASSERT_EQ(slice.size(), 2u);
  EXPECT_DOUBLE_EQ(slice[0].axial_flow, 0.0321);
  EXPECT_DOUBLE_EQ(slice[1].axial_flow, 0.0298);
  fs::remove_all(d);
}
