// The strict YAML reader: unknown keys, wrong types and out-of-range values are
// errors naming the key path, the line, the value and the allowed range.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "config/strict_yaml.hpp"
#include "tests/yaml_abuse.hpp"

using centrec::config::ConfigError;
using centrec::config::MapReader;
using centrec::config::Range;

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(StrictYaml, ReadsValuesAndRecordsDefaults) {
  auto r = MapReader::from_string("drum:\n  diameter: 0.12\n  speed_rpm: 160.08\n", "case.yaml");
  auto drum = r.child("drum");
  EXPECT_DOUBLE_EQ(drum.number("diameter", 1.0, Range::positive(), "m"), 0.12);
  EXPECT_DOUBLE_EQ(drum.number("speed_rpm", 0.0, Range::non_negative()), 160.08);
  EXPECT_DOUBLE_EQ(drum.number("tilt_deg", 45.0, Range::closed(0, 90)), 45.0);
  drum.finish();
  r.finish();
  const std::string text = r.resolved_text();
  EXPECT_NE(text.find("tilt_deg: 45"), std::string::npos) << text;
  EXPECT_NE(text.find("diameter: 0.12"), std::string::npos) << text;
}

TEST(StrictYaml, UnknownKeyNamesPathAndLine) {
  auto r = MapReader::from_string("drum:\n  diameter: 0.12\n  diamter: 0.2\n", "case.yaml");
  auto drum = r.child("drum");
  drum.number("diameter", 1.0, Range::positive());
  const std::string msg = error_of([&] { drum.finish(); });
  EXPECT_NE(msg.find("case.yaml:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("drum.diamter"), std::string::npos) << msg;
}

TEST(StrictYaml, OutOfRangeNamesValueAndRange) {
  auto r = MapReader::from_string("drum:\n  diameter: -0.5\n", "case.yaml");
  auto drum = r.child("drum");
  const std::string msg = error_of([&] { drum.number("diameter", 1.0, Range::positive(), "m"); });
  EXPECT_NE(msg.find("case.yaml:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("drum.diameter = -0.5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
}

TEST(StrictYaml, WrongTypeIsAnError) {
  auto r = MapReader::from_string("steps: many\nflag: maybe\nmode: fast\nv: [1, 2]\n", "c.yaml");
  EXPECT_NE(error_of([&] { r.integer("steps", 1, 0, 10); }).find("steps = 'many' is not a number"),
            std::string::npos);
  EXPECT_NE(error_of([&] { r.boolean("flag", false); }).find("must be true or false"), std::string::npos);
  EXPECT_NE(error_of([&] { r.choice("mode", "slow", {"slow", "exact"}); }).find("not one of {slow, exact}"),
            std::string::npos);
  EXPECT_NE(error_of([&] { r.vec3("v", {0, 0, 0}); }).find("needs 3"), std::string::npos);
}

TEST(StrictYaml, IntegerRejectsFraction) {
  auto r = MapReader::from_string("n: 2.5\n", "c.yaml");
  EXPECT_NE(error_of([&] { r.integer("n", 1, 0, 10); }).find("must be an integer"), std::string::npos);
}

TEST(StrictYaml, ReadingAbsentKeyDoesNotInsertIt) {
  auto r = MapReader::from_string("a: 1\n", "c.yaml");
  r.number("a", 0, Range::any());
  r.number("b", 2, Range::any());
  EXPECT_NO_THROW(r.finish());
}

// What yaml-cpp accepts but a case file must not be: no document, two documents, an alias
// that holds itself, aliases that expand beyond any case, and a reading cost that grows
// faster than the file (docs/reliability.md "Case files").
TEST(StrictYaml, AFileWithoutKeysIsNotACase) {
  for (const char* text : {"", "   \n\n", "# only a comment\n# and another\n"}) {
    const std::string msg = error_of([&] { MapReader::from_string(text, "c.yaml"); });
    std::printf("'%s' -> %s\n", text, msg.c_str());
    EXPECT_NE(msg.find("c.yaml: holds no case"), std::string::npos) << msg;
  }
}

TEST(StrictYaml, ASecondDocumentIsRefused) {
  const std::string msg = error_of([] { MapReader::from_string("a: 1\n---\ndem: {drum: oops}\n", "c.yaml"); });
  std::printf("%s\n", msg.c_str());
  EXPECT_NE(msg.find("c.yaml:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("second YAML document"), std::string::npos) << msg;
}

TEST(StrictYaml, AnAliasThatHoldsItselfIsRefused) {
  for (const char* text : {"a: &x [*x]\n", "a: &x {b: *x}\n"}) {
    const std::string msg = error_of([&] { MapReader::from_string(text, "c.yaml"); });
    std::printf("%s -> %s\n", text, msg.c_str());
    EXPECT_NE(msg.find("c.yaml:1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("refers to itself"), std::string::npos) << msg;
  }
}

TEST(StrictYaml, AliasesThatExpandBeyondAnyCaseAreRefusedAtOnce) {
  const std::string text = centrec::testing::alias_bomb();  // 1e9 values once expanded
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = error_of([&] { MapReader::from_string(text, "c.yaml"); });
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%.3f s: %s\n", s, msg.c_str());
  EXPECT_NE(msg.find("aliases"), std::string::npos) << msg;
  // The reader stops at 1e6 expanded values (~0.1 s plain, ~1 s under the sanitizers, more with
  // a DEM beside it); expanding all 1e9 would take a thousand times that.
  EXPECT_LT(s, 10.0);
}

TEST(StrictYaml, ReadingCostGrowsWithTheFileNotItsSquare) {
  // 200,000 distinct keys: a check that compares every key with every other takes ~20 s. The
  // cost of 200,000 keys over that of 20,000 is ~10 when it grows with the file and ~100 when
  // it grows with its square; a ratio, so a loaded machine (CI, a DEM run beside) slows both.
  auto seconds_for = [](int keys, std::string& msg) {
    std::string text;
    for (int k = 0; k < keys; ++k) text += "key_" + std::to_string(k) + ": 1\n";
    double best = 1e300;
    for (int rep = 0; rep < 2; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      auto r = MapReader::from_string(text, "c.yaml");
      msg = error_of([&] { r.finish(); });
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
  };
  std::string small_msg, msg;
  const double small = seconds_for(20000, small_msg), s = seconds_for(200000, msg);
  std::printf("20000 keys in %.3f s, 200000 keys read and refused in %.3f s (x %.1f): %.80s\n", small, s, s / small,
              msg.c_str());
  EXPECT_NE(msg.find("key_"), std::string::npos) << msg;
  EXPECT_LT(s / small, 40.0);
  EXPECT_LT(s, 30.0);
}
