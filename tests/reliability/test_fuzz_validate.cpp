// Fuzzing the case reader (docs/reliability.md): a few hundred mutations of the shipped
// cases (fixed seed) through `centrec validate`. None may crash or hang; every refusal must
// name the line (file:N) or the key it concerns. Prints the table of categories tried /
// refused clearly / accepted / unclear / crash / hang that docs/reliability.md reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "tests/reliability/run_binary.hpp"
#include "thermal/analytic_film.hpp"
#include "tests/test_case_dir.hpp"
#include "tests/yaml_abuse.hpp"

using centrec::testing::BinaryRun;
using centrec::testing::run_binary;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> v;
  std::size_t a = 0;
  for (std::size_t b; (b = text.find('\n', a)) != std::string::npos; a = b + 1) v.push_back(text.substr(a, b - a));
  if (a < text.size()) v.push_back(text.substr(a));
  return v;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& l : v) s += l + "\n";
  return s;
}

// Lines that hold a value (not comments or blank lines).
std::vector<std::size_t> content_lines(const std::vector<std::string>& v) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i].find_first_not_of(' ') != std::string::npos && v[i][v[i].find_first_not_of(' ')] != '#') idx.push_back(i);
  return idx;
}

// A clear refusal of case.yaml names the file and a line, or the file and a key path.
bool refused_clearly(const BinaryRun& r) {
  static const std::regex clear(
      "case\\.yaml(:[0-9]+: |: [A-Za-z_]+[.:\\[ ]| \\(resolved configuration\\)|: (no such|not a|the case|larger|holds "
      "no case))");
  return r.exit_code == 2 && std::regex_search(r.err, clear) && std::count(r.err.begin(), r.err.end(), '\n') == 1;
}

struct Mutator {
  std::mt19937_64 rng;
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
  template <class T>
  const T& any(const std::vector<T>& v) { return v[pick(v.size())]; }

  // Mutates `text` by one operator of `category`; returns the new text.
  std::string apply(const std::string& category, const std::string& text) {
    std::vector<std::string> v = lines_of(text);
    const std::vector<std::size_t> c = content_lines(v);
    if (category == "yaml") return yaml_abuse(v, c);
    if (c.empty()) return text + "x: 1\n";  // a case truncated to nothing: give it a line
    std::string& line = v[any(c)];
    if (category == "number") {
      static const std::vector<std::string> bad = {"0", "-1", "1e300", "-1e300", "1e-300", "nan", "inf", "-inf", ".nan",
                                                   ".inf", "1e400", "9223372036854775808", "-9223372036854775809",
                                                   "abc", "0x10", "1_000", "1,5", "\"2\"", "[1, 2]", "{a: 1}", "true",
                                                   "2.0e-4", "1e9", "-0", "3.5"};
      // Replace one number of the line, or append one as a value of a new key.
      static const std::regex num(R"([-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)");
      std::vector<std::pair<std::size_t, std::size_t>> spans;
      for (auto it = std::sregex_iterator(line.begin(), line.end(), num); it != std::sregex_iterator(); ++it)
        spans.emplace_back(it->position(), it->length());
      if (spans.empty()) return text;
      const auto [at, len] = any(spans);
      line.replace(at, len, any(bad));
    } else if (category == "structure") {
      const int op = static_cast<int>(pick(5));
      const std::size_t i = any(c);
      if (op == 0) v.erase(v.begin() + static_cast<long>(i));                       // delete a line
      else if (op == 1) v.insert(v.begin() + static_cast<long>(i), v[i]);           // duplicate a line (key twice)
      else if (op == 2) std::swap(v[i], v[any(c)]);                                 // swap two lines
      else if (op == 3) v[i] = "  " + v[i];                                         // indent
      else if (v[i].rfind("  ", 0) == 0) v[i] = v[i].substr(2);                     // dedent
    } else if (category == "key") {
      const std::size_t colon = line.find(':');
      if (colon == std::string::npos) return text;
      const std::size_t start = line.find_first_not_of(" {-");
      if (start >= colon) return text;
      std::string key = line.substr(start, colon - start);
      const int op = static_cast<int>(pick(4));
      if (op == 0) for (char& ch : key) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      else if (op == 1 && key.size() > 1) key.erase(pick(key.size()), 1);
      else if (op == 2) key += "s";
      else key = "unknown_" + key;
      line.replace(start, colon - start, key);
    } else if (category == "value") {
      const std::size_t colon = line.find(':');
      if (colon == std::string::npos) return text;
      const int op = static_cast<int>(pick(4));
      if (op == 0) line = line.substr(0, colon + 1);               // empty value (a whole section or a number)
      else if (op == 1) line = line.substr(0, colon + 1) + " null";
      else if (op == 2) line = line.substr(0, colon + 1) + " \"unterminated";
      else line = line.substr(0, colon + 1) + " '" + line.substr(colon + 1);
    } else if (category == "bytes") {
      static const std::vector<std::string> junk = {"\xff", "\xc3", "\xe2\x82", "\t", "\"", "'", ":", "{", "}", "[",
                                                    "]", "- ", "&a", "*a", "!!binary", "%", "@", "`", "\0", "\r",
                                                    "? ", "|", ">", "#"};
      std::string s = join(v);
      const std::size_t at = pick(s.size() + 1);
      const std::string& j = any(junk);
      s.insert(at, j.empty() ? std::string(1, '\0') : j);
      return s;
    } else if (category == "truncate") {
      const std::string s = join(v);
      return s.substr(0, pick(s.size() + 1));
    }
    return join(v);
  }

  // What no case file is, though YAML allows it: every result must be refused.
  std::string yaml_abuse(std::vector<std::string> v, const std::vector<std::size_t>& c) {
    const int op = static_cast<int>(pick(7));
    if (op == 0) return "";                      // empty
    if (op == 1) return " \n\t\n   \n";          // whitespace only
    if (op == 2) {                               // every line commented out
      for (auto& l : v) l = "# " + l;
      return join(v);
    }
    if (op == 3) return join(v) + "---\n" + join(v);  // a second document
    if (op == 4) {                               // an alias inside its own anchor
      v.insert(v.begin() + static_cast<long>(c.empty() ? 0 : any(c)), pick(2) ? "loop: &self [*self]" : "loop: &self {a: *self}");
      return join(v);
    }
    if (op == 5) {                               // aliases that expand to 1e9 values
      const std::string bomb = centrec::testing::alias_bomb();
      return pick(2) ? bomb + join(v) : join(v) + bomb;
    }
    std::string keys;                            // 20,000 unknown keys
    for (int k = 0; k < 20000; ++k) keys += "unknown_" + std::to_string(k) + ": 1\n";
    return join(v) + keys;
  }
};

}  // namespace

TEST(FuzzValidate, MutatedCasesNeverCrashHangOrRefuseVaguely) {
  const std::string dir = centrec::testing::fresh_dir("fuzz");
  // The flux table receiver_1m.yaml reads, beside the mutated case.
  std::filesystem::copy_file(CENTREC_SOURCE_DIR "/cases/receiver_flux.csv", dir + "/receiver_flux.csv");
  const std::vector<std::string> seeds = {"quickstart.yaml", "receiver_1m.yaml", "d12.yaml", "d12_slice.yaml",
                                          "thermal_centrec_uniform.yaml", "thermal_cloud_transient.yaml",
                                          "thermal_centrec_cavity.yaml"};
  std::vector<std::string> texts;
  for (const auto& s : seeds) texts.push_back(slurp(CENTREC_SOURCE_DIR "/cases/" + s));
  const std::vector<std::string> categories = {"number", "structure", "key", "value", "bytes", "truncate", "yaml"};
  constexpr int kPerCategory = 50;

  struct Tally {
    int tried = 0, refused = 0, accepted = 0, unclear = 0, crash = 0, hang = 0;
  };
  std::map<std::string, Tally> tally;
  Mutator m{std::mt19937_64(20261202)};
  const std::string path = dir + "/case.yaml";
  for (const auto& cat : categories) {
    for (int k = 0; k < kPerCategory; ++k) {
      const std::size_t which = m.pick(texts.size());
      std::string text = m.apply(cat, texts[which]);
      if (m.pick(4) == 0) text = m.apply(cat, text);  // sometimes two mutations
      std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
      const BinaryRun r = run_binary({"validate", path}, 10.0);
      Tally& t = tally[cat];
      ++t.tried;
      if (r.timed_out) {
        ++t.hang;
        ADD_FAILURE() << "hang on a mutation of " << seeds[which] << ":\n" << text;
      } else if (r.signal != 0) {
        ++t.crash;
        ADD_FAILURE() << "signal " << r.signal << " on a mutation of " << seeds[which] << ":\n" << text;
      } else if (r.exit_code == 0) {
        ++t.accepted;
        if (cat == "yaml") ADD_FAILURE() << "accepted as a case:\n" << text.substr(0, 400);
      } else if (refused_clearly(r)) {
        ++t.refused;
      } else {
        ++t.unclear;
        ADD_FAILURE() << "unclear refusal (exit " << r.exit_code << "): " << r.err << "of a mutation of " << seeds[which]
                      << ":\n" << text;
      }
    }
  }
  std::printf("| category | tried | refused clearly | accepted | unclear | crash | hang |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  Tally all;
  for (const auto& cat : categories) {
    const Tally& t = tally[cat];
    std::printf("| %s | %d | %d | %d | %d | %d | %d |\n", cat.c_str(), t.tried, t.refused, t.accepted, t.unclear,
                t.crash, t.hang);
    all.tried += t.tried, all.refused += t.refused, all.accepted += t.accepted, all.unclear += t.unclear;
    all.crash += t.crash, all.hang += t.hang;
  }
  std::printf("| all | %d | %d | %d | %d | %d | %d |\n", all.tried, all.refused, all.accepted, all.unclear, all.crash,
              all.hang);
  EXPECT_EQ(all.tried, kPerCategory * static_cast<int>(categories.size()));
  std::filesystem::remove_all(dir);
}

// The categories of input a held-out probe found accepted as if it were physics, or accepted
// by `validate` and refused only by the run (docs/reliability.md section 4), each as edits of
// a shipped case: every one must now be refused clearly by `validate`, naming the line or key.
TEST(FuzzValidate, TheProbesCategoriesAreRefusedClearly) {
  const std::string dir = centrec::testing::fresh_dir("fuzz_named");
  const std::string path = dir + "/case.yaml";
  auto shipped = [](const std::string& name) { return slurp(CENTREC_SOURCE_DIR "/cases/" + name); };
  auto edited = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  const std::string drum = shipped("drum_dd80/paper_length_loose.yaml"), uniform = shipped("thermal_centrec_uniform.yaml"),
                    cavity = shipped("thermal_centrec_cavity.yaml"), quick = shipped("quickstart.yaml");
  struct Probe {
    const char* category;
    std::string text;
  };
  const std::vector<Probe> probes = {
      {"no case", ""},
      {"no case", "   \n\n"},
      {"no case", "# only a comment\n"},
      {"no case", quick + "---\ndem: {drum: {diameter: -1}}\n"},
      {"temperature", edited(cavity, "T_in: 873.15", "T_in: 3000")},
      {"temperature", edited(cavity, "T_in: 873.15", "T_in: 4500")},
      {"property", edited(uniform, "thermal:\n", "thermal:\n  material: {k_s: 1e-300}\n")},
      {"property", edited(uniform, "thermal:\n", "thermal:\n  heat_capacity: {model: constant, cp: 1e-300}\n")},
      {"property", edited(uniform, "thermal:\n", "thermal:\n  conductivity: {model: constant, k: 1e300}\n")},
      {"geometry", edited(drum, "dem:\n", "dem:\n  gravity: 0\n")},
      {"geometry", edited(drum, "particles: 62000}", "particles: 1000, axial_from: 0.5}")},
      {"geometry", edited(drum, "particles: 62000}", "particles: 2000000}")},
      {"geometry", edited(quick, "particles: 6750}", "particles: 6750, axial_from: 0.01}")},
      {"geometry", edited(quick, "receiver: {diameter: 0.12,", "receiver: {diameter: 0.0006,")},
      {"geometry", edited(uniform, "drum_diameter: 1.0", "drum_diameter: 0.01")},
      {"feeder", edited(drum, "radial_height_d: 4", "radial_height_d: 45")},
      {"feeder", edited(drum, "radial_offset_d: 10", "radial_offset_d: 1")},
      {"feeder", edited(drum, "angle_deg: 0,", "angle_deg: 0, arc_width_d: 1000,")},
      {"source run", edited(drum, "particles: 62000}", "from_run: no_such_run}")},
      {"sweep", uniform + "sweep: {speed_rpm: [50, 60], mass_flow: [0.3]}\n"},
  };
  std::map<std::string, std::array<int, 5>> tally;  // tried, refused clearly, accepted, crash, hang
  std::vector<std::string> order;
  for (const Probe& p : probes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << p.text;
    const BinaryRun r = run_binary({"validate", path}, 10.0);
    if (!tally.count(p.category)) order.push_back(p.category);
    auto& t = tally[p.category];
    ++t[0];
    if (r.timed_out) {
      ++t[4];
      ADD_FAILURE() << "hang: " << p.text.substr(0, 300);
    } else if (r.signal != 0) {
      ++t[3];
      ADD_FAILURE() << "signal " << r.signal << ": " << p.text.substr(0, 300);
    } else if (r.exit_code == 0) {
      ++t[2];
      ADD_FAILURE() << "accepted (" << p.category << "): " << p.text.substr(0, 600);
    } else if (refused_clearly(r)) {
      ++t[1];
    } else {
      ADD_FAILURE() << "unclear refusal (exit " << r.exit_code << "): " << r.err;
    }
  }
  std::printf("| category | tried | refused clearly | accepted | crash | hang |\n|---|---|---|---|---|---|\n");
  for (const auto& c : order) {
    const auto& t = tally[c];
    std::printf("| %s | %d | %d | %d | %d | %d |\n", c.c_str(), t[0], t[1], t[2], t[3], t[4]);
  }
  std::filesystem::remove_all(dir);
}

// The files a case reads beside it, mutated: the flux table (receiver_1m.yaml's CSV: numbers,
// lines, bytes, truncation) and a stored film field (film.h5 with bytes flipped). `validate`
// reads both as the runs do; each mutation must be accepted or refused in one line naming
// the file, never crash or hang.
TEST(FuzzValidate, MutatedTablesAndFilmFilesNeverCrashOrHang) {
  const std::string dir = centrec::testing::fresh_dir("fuzz_tables");
  const std::string table = slurp(CENTREC_SOURCE_DIR "/cases/receiver_flux.csv");
  std::filesystem::copy_file(CENTREC_SOURCE_DIR "/cases/receiver_1m.yaml", dir + "/receiver_1m.yaml");
  // A film field written as `centrec run` writes film.h5 (only the film: a flipped byte lands
  // in what the reader reads), and a thermal case reading it.
  const std::string film_h5 = dir + "/film.h5";
  {
    centrec::io::H5File f = centrec::io::H5File::create(film_h5);
    centrec::io::write_film_field(f, centrec::thermal::analytic_film(centrec::thermal::AnalyticFilm{}));
    f.commit();
  }
  std::string uniform = slurp(CENTREC_SOURCE_DIR "/cases/thermal_centrec_uniform.yaml");
  const std::size_t a = uniform.find("film:\n"), b = uniform.find("thermal:\n");
  ASSERT_TRUE(a != std::string::npos && b != std::string::npos && a < b);
  std::ofstream(dir + "/film_case.yaml") << uniform.substr(0, a) << "film: {file: film.h5}\n" << uniform.substr(b);
  ASSERT_EQ(run_binary({"validate", dir + "/film_case.yaml"}, 10.0).exit_code, 0) << "the unmutated film case";
  const std::string film = slurp(film_h5);

  struct Tally {
    int tried = 0, refused = 0, accepted = 0, unclear = 0, crash = 0, hang = 0;
  };
  std::map<std::string, Tally> tally;
  std::vector<std::string> order;
  Mutator m{std::mt19937_64(20261206)};
  auto judge = [&](const std::string& what, const std::string& file, const BinaryRun& r, const std::string& note) {
    if (!tally.count(what)) order.push_back(what);
    Tally& t = tally[what];
    ++t.tried;
    if (r.timed_out) {
      ++t.hang;
      ADD_FAILURE() << "hang (" << what << "): " << note;
    } else if (r.signal != 0) {
      ++t.crash;
      ADD_FAILURE() << "signal " << r.signal << " (" << what << "): " << note;
    } else if (r.exit_code == 0) {
      ++t.accepted;
    } else if (r.exit_code == 2 && r.err.find(file) != std::string::npos &&
               std::count(r.err.begin(), r.err.end(), '\n') == 1) {
      ++t.refused;
    } else {
      ++t.unclear;
      ADD_FAILURE() << "unclear refusal (" << what << ", exit " << r.exit_code << "): " << r.err << note;
    }
  };
  for (const char* cat : {"number", "structure", "bytes", "truncate"})
    for (int k = 0; k < 25; ++k) {
      const std::string text = m.apply(cat, table);
      std::ofstream(dir + "/receiver_flux.csv", std::ios::binary | std::ios::trunc) << text;
      judge(std::string("flux table: ") + cat, "receiver_flux.csv",
            run_binary({"validate", dir + "/receiver_1m.yaml"}, 10.0), text.substr(0, 300));
    }
  for (int k = 0; k < 50; ++k) {
    std::string bytes = film;
    const int flips = 1 + static_cast<int>(m.pick(16));
    for (int f = 0; f < flips; ++f) bytes[m.pick(bytes.size())] = static_cast<char>(m.pick(256));
    std::ofstream(film_h5, std::ios::binary | std::ios::trunc) << bytes;
    judge("film file: bytes", "film.h5", run_binary({"validate", dir + "/film_case.yaml"}, 10.0),
          std::to_string(flips) + " bytes changed");
  }
  std::printf("| file | tried | refused clearly | accepted | unclear | crash | hang |\n|---|---|---|---|---|---|---|\n");
  for (const auto& w : order) {
    const Tally& t = tally[w];
    std::printf("| %s | %d | %d | %d | %d | %d | %d |\n", w.c_str(), t.tried, t.refused, t.accepted, t.unclear,
                t.crash, t.hang);
  }
  std::filesystem::remove_all(dir);
}
