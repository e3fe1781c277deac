#include "config/case_keys.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/case_file.hpp"

namespace centrec::config {

namespace {

// A coupled case with every section at its defaults: it reads every key that has no
// branch. The DEM needs sampled turns and the receiver its operating point (the paper's D12).
const char* const kCoupled = R"(title: keys
description: keys
dem: {sampling: {turns: 1}}
receiver: {diameter: 0.12, length: 0.171, speed_rpm: 160.08, mass_flow: 0.0357RECEIVER}
thermal: {THERMAL}
sweep: {speed_rpm: [160.08], mass_flow: [0.0357]}
)";
// A thermal-only case on an analytic film.
const char* const kThermal = "film: {analytic: {}}\nthermal: {THERMAL}\n";

// One case the readers read: `when` names the branch it takes ("" = none worth naming);
// `may_fail`: it names a file that does not exist, so its reader stops at that key (the
// keys before it are recorded); `optional`: the keys it adds are read only when given.
struct Walk {
  std::string when;
  std::string yaml;
  bool may_fail = false;
  bool optional = false;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}
std::string coupled(const std::string& thermal, const std::string& receiver = "") {
  return replaced(replaced(kCoupled, "THERMAL", thermal), "RECEIVER", receiver);
}
std::string thermal(const std::string& t) { return replaced(kThermal, "THERMAL", t); }

std::vector<Walk> walks() {
  std::vector<Walk> w = {
      {"", coupled("")},
      {"", coupled("", ", particle_diameter: 1.2e-3"), false, true},
      {"", thermal("")},
      {"", "film: {file: no-such-film.h5}\nthermal: {}\n", true},
      {"thermal.radiation.model: open_surface", thermal("radiation: {model: open_surface}")},
      {"thermal.flux.profile: gaussian", thermal("flux: {profile: gaussian}")},
      {"instead of thermal.flux.q_film", thermal("flux: {q_aperture: 1.0e6}"), false, true},
      {"thermal.flux.profile: table", thermal("flux: {profile: table, table_file: no-such-table.csv}"), true},
      {"thermal.flux.absorption: layers", thermal("flux: {absorption: layers}")},
      {"thermal.radiation.film_top: two_flux", thermal("radiation: {film_top: two_flux}")},
      {"thermal.conductivity.model: constant", thermal("conductivity: {model: constant, k: 1}")},
      {"thermal.heat_capacity.model: constant", thermal("heat_capacity: {model: constant, cp: 1000}")},
      {"", thermal("transient: {t_end: 10}")},
      {"kind: step or pulse", thermal("flux: {time: {kind: step}}, transient: {t_end: 10, mass_flow: {kind: step}}")},
      {"kind: pulse", thermal("flux: {time: {kind: pulse}}, transient: {t_end: 10, mass_flow: {kind: pulse}}")},
      {"a coupled case", coupled("") + "film: {mapping: as_measured}\n", false, true},
  };
  // Each rolling model with coefficients of its own: its keys beside rolling_model.
  for (const dem::RollingModelInfo& m : dem::kRollingModels) {
    if (!m.coefficients[0].key) continue;
    const std::string pair = std::string("{rolling_model: ") + m.name + "}";
    w.push_back({std::string("dem.contacts.*.rolling_model: ") + m.name,
                 replaced(coupled(""), "dem: {sampling: {turns: 1}}",
                          "dem: {sampling: {turns: 1}, contacts: {particle_particle: " + pair +
                              ", particle_wall: " + pair + "}}")});
  }
  return w;
}

// The top-level part of a key path ("" for the top-level keys themselves).
std::string section_of(const std::string& path) {
  const std::size_t dot = path.find('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

// Inserts `k` after the last key that shares its parent path, so that keys a branch adds
// stand beside their siblings.
void insert_beside_siblings(std::vector<ReferencedKey>& out, ReferencedKey k) {
  const std::size_t dot = k.key.path.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : k.key.path.substr(0, dot);
  std::size_t at = out.size();
  if (!parent.empty())
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out[i].key.path == parent || out[i].key.path.compare(0, parent.size() + 1, parent + ".") == 0) at = i + 1;
  out.insert(out.begin() + static_cast<long>(at), std::move(k));
}

std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::vector<ReferencedKey> case_keys() {
  std::vector<ReferencedKey> out;
  for (const Walk& w : walks()) {
    std::vector<KeyRecord> read;
    try {
      read_case_recording(w.yaml, "<key reference case>", read);
    } catch (const ConfigError& e) {
      if (!w.may_fail)
        throw std::logic_error(std::string("the key reference's case failed to read: ") + e.what() + "\n" + w.yaml);
    }
    for (KeyRecord& k : read) {
      const bool known = std::any_of(out.begin(), out.end(), [&](const ReferencedKey& r) { return r.key.path == k.path; });
      if (known) continue;
      if (w.optional) k.default_value = "(none)";
      insert_beside_siblings(out, {std::move(k), w.when});
    }
  }
  // Sections in the order of the case file's known keys; the top-level keys first.
  const std::vector<std::string> order = {"", "dem", "receiver", "film", "thermal", "sweep"};
  auto rank = [&](const ReferencedKey& r) {
    const std::string s = section_of(r.key.path).empty() ? r.key.path : section_of(r.key.path);
    const auto it = std::find(order.begin(), order.end(), s);
    return it == order.end() ? (r.key.type == "section" ? order.size() : 0) : static_cast<std::size_t>(it - order.begin());
  };
  std::stable_sort(out.begin(), out.end(), [&](const ReferencedKey& a, const ReferencedKey& b) { return rank(a) < rank(b); });
  return out;
}

std::string case_keys_markdown(const std::vector<ReferencedKey>& keys) {
  std::string md =
      "# Case-file keys\n\n"
      "Every key a case file (YAML) may hold, with its type, default, allowed values, unit and meaning.\n"
      "Generated by `centrec keys` from the section readers themselves (apps/config/), which record each\n"
      "key as they read it; do not edit by hand. Regenerate with\n\n"
      "    ./build/centrec keys > docs/case_keys.md\n\n"
      "(the default suite's `CaseKeys` test fails while this file differs from what the readers say).\n"
      "Units and names: [conventions.md](conventions.md) (SI unless the key names its unit; `_d` keys in\n"
      "particle diameters of `dem.particles.diameter`). Ranges: `[` closed, `(` open; a range that depends on\n"
      "another key is shown at that key's default and the meaning says what it depends on. A key read only\n"
      "on a branch says so (\"only with ...\"). Reading is strict: an unknown key, a wrong type or a value out\n"
      "of range is refused with the file, line and key ([reliability.md](reliability.md)).\n";
  std::string section = "\x01";
  for (const ReferencedKey& r : keys) {
    const KeyRecord& k = r.key;
    if (k.meaning.empty())
      throw std::logic_error("case key " + k.path +
                             " has no meaning: give its one-line meaning where its reader reads it (apps/config/)");
    const std::string s = k.type == "section" && section_of(k.path).empty() ? k.path : section_of(k.path);
    if (s != section) {
      section = s;
      md += "\n## " + (s.empty() ? std::string("Top level") : "`" + s + ":`") + "\n\n";
      md += "| key | type | default | allowed | unit | meaning |\n|---|---|---|---|---|---|\n";
    }
    std::string meaning = k.meaning;
    if (!r.when.empty()) meaning += " (only with `" + r.when + "`)";
    md += "| `" + cell(k.path) + "` | " + k.type + " | " + (k.default_value.empty() ? "" : "`" + cell(k.default_value) + "`") +
          " | " + cell(k.allowed) + " | " + cell(k.unit) + " | " + cell(meaning) + " |\n";
  }
  return md;
}

}  // namespace centrec::config
