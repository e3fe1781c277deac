// The DEM cache of `centrec run` (docs/reliability.md): an entry's dem.h5 and summary.json
// are checked against the checksums recorded when it was made (one flipped bit is refused,
// naming the file); a run that fails before its first checkpoint leaves no folder behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "runs/dem_cache.hpp"
#include "tests/test_case_dir.hpp"

using namespace centrec;
namespace fs = std::filesystem;

namespace {
// A stand-in DEM run: writes the two files the coupled run reads back.
void fake_run(const std::string& dir, bool) {
  fs::create_directories(dir);
  std::ofstream(dir + "/dem.h5", std::ios::binary) << std::string(4096, '\x11');
  std::ofstream(dir + "/summary.json") << "{\"holdup_kg\": 0.01}\n";
}
}  // namespace

TEST(DemCacheIntegrity, AFlippedBitInACachedFileIsRefusedNamingIt) {
  const std::string cache = centrec::testing::fresh_dir("cache_integrity") + "/cache";
  int runs = 0;
  auto run = [&](const std::string& dir, bool resume) {
    ++runs;
    fake_run(dir, resume);
  };
  const runs::CachedDem first = runs::cached_dem_run(cache, "abc", run);
  EXPECT_FALSE(first.hit);
  EXPECT_TRUE(fs::exists(first.dir + "/checksums.txt"));
  const runs::CachedDem second = runs::cached_dem_run(cache, "abc", run);
  EXPECT_TRUE(second.hit);
  EXPECT_EQ(runs, 1);
  {
    std::fstream f(first.dir + "/dem.h5", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(2000);
    f.put('\x13');  // one bit flipped
  }
  try {
    runs::cached_dem_run(cache, "abc", run);
    ADD_FAILURE() << "a damaged cache entry was used";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(first.dir + "/dem.h5: checksum mismatch"), std::string::npos) << msg;
    EXPECT_NE(msg.find("remove " + first.dir), std::string::npos) << msg;
  }
  EXPECT_EQ(runs, 1);
  // A corrupt summary.json is named too (it used to fail in the JSON parser, unnamed).
  fake_run(first.dir, false);
  std::ofstream(first.dir + "/summary.json") << "{\"holdup_kg\": 0.0";
  try {
    runs::cached_dem_run(cache, "abc", run);
    ADD_FAILURE() << "a damaged summary.json was used";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(first.dir + "/summary.json: checksum mismatch"), std::string::npos) << e.what();
  }
}

TEST(DemCacheIntegrity, AFailedRunLeavesNoEmptyFolders) {
  const std::string root = centrec::testing::fresh_dir("cache_cleanup");
  const std::string cache = root + "/new/cache";
  EXPECT_THROW(runs::cached_dem_run(cache, "abc",
                                    [](const std::string& dir, bool) {
                                      fs::create_directories(dir);
                                      throw std::runtime_error("set-up failed");
                                    }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(root + "/new")) << "the cache folder it created was left behind";
  // A run stopped after a checkpoint keeps its folder to continue from.
  EXPECT_THROW(runs::cached_dem_run(cache, "abc",
                                    [](const std::string& dir, bool) {
                                      fs::create_directories(dir);
                                      std::ofstream(dir + "/checkpoint.h5") << "x";
                                      throw std::runtime_error("stopped");
                                    }),
               std::runtime_error);
  EXPECT_TRUE(fs::exists(cache));
  fs::remove_all(root);
}
