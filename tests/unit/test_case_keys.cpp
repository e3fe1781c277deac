// The case-key reference (docs/case_keys.md) is what the readers say: regenerated from
// the section readers (config::case_keys, as `centrec keys` prints it), it must equal the
// committed file byte for byte; every key of every shipped case must be in it; a key whose
// reader gives no meaning stops the generation, naming the key.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

#include "config/case_keys.hpp"

using namespace centrec;

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Every key path in a YAML tree (list indices dropped).
void key_paths(const YAML::Node& n, const std::string& at, std::set<std::string>& out) {
  if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string p = at.empty() ? it->first.Scalar() : at + "." + it->first.Scalar();
      out.insert(p);
      key_paths(it->second, p, out);
    }
  } else if (n.IsSequence()) {
    for (const auto& e : n) key_paths(e, at, out);
  }
}
}  // namespace

TEST(CaseKeys, TheCommittedReferenceIsWhatTheReadersSay) {
  const std::string generated = config::case_keys_markdown(config::case_keys());
  const std::string committed = slurp(CENTREC_SOURCE_DIR "/docs/case_keys.md");
  if (generated != committed) {
    std::size_t at = 0;
    while (at < generated.size() && at < committed.size() && generated[at] == committed[at]) ++at;
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(generated.begin(), generated.begin() + static_cast<long>(at), '\n'));
    ADD_FAILURE() << "docs/case_keys.md differs from what the case readers say (first at line " << line
                  << "): regenerate it with `./build/centrec keys > docs/case_keys.md` and commit it";
  }
  std::printf("docs/case_keys.md: %zu keys, %zu bytes\n", config::case_keys().size(), generated.size());
}

TEST(CaseKeys, EveryKeyOfEveryShippedCaseIsInTheReference) {
  std::set<std::string> documented;
  for (const auto& k : config::case_keys()) documented.insert(k.key.path);
  std::size_t cases = 0, keys = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(CENTREC_SOURCE_DIR "/cases")) {
    if (e.path().extension() != ".yaml") continue;
    std::set<std::string> used;
    key_paths(YAML::LoadFile(e.path().string()), "", used);
    for (const auto& k : used) {
      EXPECT_TRUE(documented.count(k)) << e.path() << ": key " << k << " is not in the key reference";
      ++keys;
    }
    ++cases;
  }
  EXPECT_GT(cases, 10u);
  std::printf("%zu shipped cases, %zu key uses, all in the reference of %zu keys\n", cases, keys, documented.size());
}

TEST(CaseKeys, EachKeyHasItsTypeDefaultAndRange) {
  const auto keys = config::case_keys();
  auto find = [&](const std::string& path) -> const config::KeyRecord& {
    for (const auto& k : keys)
      if (k.key.path == path) return k.key;
    throw std::runtime_error(path + " is not in the reference");
  };
  EXPECT_EQ(find("dem.drum.diameter").type, "number");
  EXPECT_EQ(find("dem.drum.diameter").default_value, "0.12");
  EXPECT_EQ(find("dem.drum.diameter").allowed, "(0, inf)");
  EXPECT_EQ(find("dem.drum.diameter").unit, "m");
  EXPECT_EQ(find("dem.run.threads").allowed, "[0, 1024]");
  EXPECT_EQ(find("thermal.flux.profile").allowed, "uniform, gaussian, table");
  EXPECT_EQ(find("receiver.mass_flow").default_value, "required");
  EXPECT_EQ(find("receiver.particle_diameter").default_value, "(none)");
  // Keys only a branch reads are there, and say which branch.
  for (const auto& k : keys) {
    if (k.key.path == "thermal.flux.q_film_peak") {
      EXPECT_EQ(k.when, "thermal.flux.profile: gaussian");
    }
  }
  EXPECT_EQ(find("film.file").type, "text");
  EXPECT_EQ(find("thermal.transient.mass_flow.t_end").unit, "s");
}

TEST(CaseKeys, AKeyWithoutMeaningStopsTheGeneration) {
  auto keys = config::case_keys();
  ASSERT_FALSE(keys.empty());
  EXPECT_NO_THROW(config::case_keys_markdown(keys));
  keys[keys.size() / 2].key.meaning.clear();
  try {
    config::case_keys_markdown(keys);
    ADD_FAILURE() << "a key without meaning was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find(keys[keys.size() / 2].key.path + " has no meaning"), std::string::npos) << e.what();
  }
}
