#include "config/strict_yaml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_set>

namespace centrec::config {

namespace {
std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string line_of(const std::string& source, const YAML::Mark& m) {
  return m.line < 0 ? source : source + ":" + std::to_string(m.line + 1);
}

// The first byte of `text` that is not part of valid UTF-8, or npos.
std::size_t invalid_utf8_at(const std::string& text) {
  const auto* b = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned c = b[i];
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || (len == 2 && c < 0xC2) || i + len > n) return i;
    for (std::size_t k = 1; k < len; ++k)
      if ((b[i + k] & 0xC0) != 0x80) return i;
    if (len == 3 && ((c == 0xE0 && b[i + 1] < 0xA0) || (c == 0xED && b[i + 1] >= 0xA0))) return i;  // overlong, surrogate
    if (len == 4 && ((c == 0xF0 && b[i + 1] < 0x90) || c > 0xF4 || (c == 0xF4 && b[i + 1] >= 0x90))) return i;
    i += len;
  }
  return std::string::npos;
}

// Bounds on a case's tree as yaml-cpp builds it. An alias shares its anchor's node, so
// a few lines of nested aliases stand for a billion values and an alias inside its own
// anchor makes a cycle; the walk below stops at either with an error instead of running
// without end (docs/reliability.md "Case files"). A case holds a few hundred values.
constexpr std::size_t kMaxCaseValues = 1000000;
constexpr std::size_t kMaxCaseDepth = 64;

// Checks what yaml-cpp accepts but a case file must not hold: a key given twice, a key
// without a value, a quoted value whose closing quote is not on its own line (an
// unterminated quote swallows the rest of the file), a key that is not a plain word, an
// alias that holds itself, aliases that expand past kMaxCaseValues or kMaxCaseDepth.
struct TreeCheck {
  const std::string& text;
  const std::string& source;
  std::vector<YAML::Node> ancestors;  // the nodes from the root down to the one checked
  std::size_t values = 0;

  void enter(const YAML::Node& n, const std::string& path) {
    for (const YAML::Node& a : ancestors)
      if (a.is(n))
        throw ConfigError(line_of(source, n.Mark()) + ": " + (path.empty() ? "the case" : path) +
                          " refers to itself (a YAML alias inside its own anchor)");
    if (++values > kMaxCaseValues || ancestors.size() >= kMaxCaseDepth)
      throw ConfigError(line_of(source, n.Mark()) + ": " + (path.empty() ? "the case" : path) +
                        ": its YAML aliases expand to more than " + std::to_string(kMaxCaseValues) +
                        " values or " + std::to_string(kMaxCaseDepth) + " levels (no case holds that many)");
    ancestors.push_back(n);
    check(n, path);
    ancestors.pop_back();
  }

  void check(const YAML::Node& n, const std::string& path) {
    if (n.IsMap()) {
      std::unordered_set<std::string> seen;
      for (auto it = n.begin(); it != n.end(); ++it) {
        if (!it->first.IsScalar())
          throw ConfigError(line_of(source, it->first.Mark()) + ": " + (path.empty() ? "" : path + ": ") +
                            "a key must be a plain word");
        const std::string& key = it->first.Scalar();
        const std::string kp = path.empty() ? key : path + "." + key;
        if (!seen.insert(key).second)
          throw ConfigError(line_of(source, it->first.Mark()) + ": " + kp +
                            " is given twice in one mapping (remove one of them)");
        if (it->second.IsNull())
          throw ConfigError(line_of(source, it->first.Mark()) + ": " + kp +
                            " has no value (give one, or remove the key for its default)");
        enter(it->second, kp);
      }
    } else if (n.IsSequence()) {
      for (std::size_t i = 0; i < n.size(); ++i) {
        const std::string kp = path + "[" + std::to_string(i) + "]";
        if (n[i].IsNull()) throw ConfigError(line_of(source, n[i].Mark()) + ": " + kp + " has no value");
        enter(n[i], kp);
      }
    } else if (n.IsScalar()) {
      check_quotes(n, path);
    }
  }

  void check_quotes(const YAML::Node& n, const std::string& path) const {
    const YAML::Mark m = n.Mark();
    if (m.pos < 0 || static_cast<std::size_t>(m.pos) >= text.size()) return;
    const char q = text[static_cast<std::size_t>(m.pos)];
    if (q != '"' && q != '\'') return;
    for (std::size_t i = static_cast<std::size_t>(m.pos) + 1; i < text.size(); ++i) {
      if (text[i] == '\n')
        throw ConfigError(line_of(source, m) + ": " + path + ": the quoted value has no closing " +
                          std::string(1, q) + " on its line (a quoted value must end on the line it starts)");
      if (q == '"' && text[i] == '\\') {
        ++i;
      } else if (text[i] == q) {
        if (q == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
          ++i;  // '' is an escaped quote
          continue;
        }
        return;
      }
    }
  }
};

// The line (1-based) of the '---' that starts the second document of `text`: the first
// document marker after some content (a '---' before any content opens the first).
int second_document_line(const std::string& text) {
  bool content = false;
  int line = 0;
  for (std::size_t a = 0; a < text.size();) {
    std::size_t b = text.find('\n', a);
    if (b == std::string::npos) b = text.size();
    const std::string l = text.substr(a, b - a);
    ++line;
    if (l.rfind("---", 0) == 0 || l.rfind("...", 0) == 0) {
      if (content) return line;
    } else if (l.find_first_not_of(" \t\r") != std::string::npos && l[l.find_first_not_of(" \t\r")] != '#') {
      content = true;
    }
    a = b + 1;
  }
  return line;
}

// Parses a whole case text strictly (see check_tree) into a mapping.
YAML::Node parse_case(const std::string& text, const std::string& source) {
  const std::size_t bad = invalid_utf8_at(text);
  if (bad != std::string::npos)
    throw ConfigError(source + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(bad), '\n')) +
                      ": the file is not valid UTF-8 text (byte " + std::to_string(bad) + ")");
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throw ConfigError(source + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(i), '\n')) +
                        ": a control character (byte " + hex + ") in the text");
    }
  }
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(source + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  // yaml-cpp reads the first document of a file and ignores the rest; a case is one.
  if (documents.size() > 1)
    throw ConfigError(source + ":" + std::to_string(second_document_line(text)) +
                      ": a second YAML document (after '---'); a case file holds one: merge them or remove one");
  if (documents.empty() || documents.front().IsNull())
    throw ConfigError(source + ": holds no case (the file is empty or only comments)");
  const YAML::Node root = documents.front();
  if (!root.IsMap()) throw ConfigError(source + ": the case must be a YAML mapping (key: value)");
  TreeCheck{text, source, {}, 0}.enter(root, "");
  return root;
}

// Edit distance, for "did you mean" suggestions.
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1,
                         prev[j - 1] + (std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                                std::tolower(static_cast<unsigned char>(b[j - 1]))
                                            ? 0
                                            : 1)});
    prev.swap(cur);
  }
  return prev[b.size()];
}
}  // namespace

std::string closest_word(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  if (best.empty() && word.size() >= 3)  // a shortened key: tilt for tilt_deg
    for (const auto& c : candidates)
      if (c.size() > word.size() && distance(word, c.substr(0, word.size())) == 0) return c;
  return best;
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Range::describe() const {
  std::string a = std::isinf(lo) ? "-inf" : fmt(lo);
  std::string b = std::isinf(hi) ? "inf" : fmt(hi);
  return std::string(lo_open || std::isinf(lo) ? "(" : "[") + a + ", " + b +
         (hi_open || std::isinf(hi) ? ")" : "]");
}

MapReader::MapReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared,
                     YAML::Node resolved_here)
    : node_(std::move(node)), path_(std::move(path)), shared_(std::move(shared)),
      resolved_here_(std::move(resolved_here)) {}

MapReader MapReader::from_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw ConfigError(path + ": no such case file");
  if (!std::filesystem::is_regular_file(path, ec)) throw ConfigError(path + ": not a case file (a directory?)");
  // A case file is a few kB; a huge one is a mistake (a data file given as the case).
  constexpr std::uintmax_t kMaxBytes = 16u << 20;
  if (std::filesystem::file_size(path, ec) > kMaxBytes)
    throw ConfigError(path + ": larger than 16 MB, not a case file");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw ConfigError(path + ": cannot open the case file (permissions?)");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) throw ConfigError(path + ": cannot read the case file");
  return from_string(text, path);
}

MapReader MapReader::from_string(const std::string& text, const std::string& source_name) {
  YAML::Node root = parse_case(text, source_name);
  auto shared = std::make_shared<Shared>();
  shared->source = source_name;
  shared->resolved = YAML::Node(YAML::NodeType::Map);
  return MapReader(root, "", shared, shared->resolved);
}

std::string MapReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

std::string MapReader::where(const YAML::Node& n) const {
  const YAML::Mark m = n.Mark();
  if (m.line < 0) return shared_->source;
  return shared_->source + ":" + std::to_string(m.line + 1);
}

void MapReader::fail(const std::string& key, const std::string& message) const {
  YAML::Node n = node_.IsMap() ? node_[key] : YAML::Node();
  std::string loc = (n && n.IsDefined()) ? where(n) : where(node_);
  throw ConfigError(loc + ": " + key_path(key) + ": " + message);
}

void MapReader::fail_path(const std::string& dotted, const std::string& message) const {
  YAML::Node n = node_;
  std::string loc = where(node_);
  for (std::size_t a = 0; a <= dotted.size();) {
    std::size_t b = dotted.find('.', a);
    if (b == std::string::npos) b = dotted.size();
    const std::string part = dotted.substr(a, b - a);
    if (!n.IsMap()) break;
    const YAML::Node& parent = n;  // const lookup: never inserts the key
    YAML::Node next = parent[part];
    if (!next.IsDefined()) break;
    loc = where(next);
    n.reset(next);
    a = b + 1;
  }
  throw ConfigError(loc + ": " + key_path(dotted) + ": " + message);
}

bool MapReader::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

std::optional<YAML::Node> MapReader::get(const std::string& key) {
  used_.push_back(key);
  if (!node_.IsMap()) return std::nullopt;
  const YAML::Node& self = node_;  // const lookup: never inserts the key
  YAML::Node n = self[key];
  if (!n.IsDefined() || n.IsNull()) return std::nullopt;
  return n;
}

double MapReader::to_number(const std::string& key, const YAML::Node& n) const {
  if (!n.IsScalar()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a number");
  const std::string s = n.Scalar();
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0')
    throw ConfigError(where(n) + ": " + key_path(key) + " = '" + s + "' is not a number");
  if (!std::isfinite(v))
    throw ConfigError(where(n) + ": " + key_path(key) + " = '" + s + "' is not a finite number");
  return v;
}

void MapReader::note(const std::string& key, const std::string& type, const std::string& default_value,
                     const std::string& allowed, const std::string& unit, const std::string& meaning) const {
  if (!shared_->recorder) return;
  const std::string p = key_path(key);
  for (const auto& k : *shared_->recorder)
    if (k.path == p) return;
  shared_->recorder->push_back({p, type, default_value, allowed, unit, meaning});
}

double MapReader::number(const std::string& key, double default_value, Range range, const std::string& unit,
                         const std::string& meaning) {
  note(key, "number", fmt(default_value), range.describe(), unit, meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  double v = on ? to_number(key, n) : default_value;
  if (!range.contains(v)) {
    throw ConfigError((on ? where(n) : where(node_)) + ": " + key_path(key) + " = " + fmt(v) +
                      " is out of the allowed range " + range.describe() + (unit.empty() ? "" : " " + unit));
  }
  resolved_here_[key] = YAML::Node(fmt(v));
  return v;
}

double MapReader::required_number(const std::string& key, Range range, const std::string& unit,
                                  const std::string& meaning) {
  note(key, "number", "required", range.describe(), unit, meaning);
  if (!has(key)) fail(key, "is required" + (unit.empty() ? std::string() : " (unit " + unit + ")"));
  return number(key, 0.0, range, unit);
}

long MapReader::integer(const std::string& key, long default_value, long lo, long hi, const std::string& meaning) {
  note(key, "integer", std::to_string(default_value), "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]", "",
       meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  long v = default_value;
  if (on) {
    double d = to_number(key, n);
    if (!std::isfinite(d) || d != std::floor(d))
      throw ConfigError(where(n) + ": " + key_path(key) + " = " + n.Scalar() + " must be an integer");
    // Range-checked as a double: a value beyond long's range cannot be converted.
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
      throw ConfigError(where(n) + ": " + key_path(key) + " = " + n.Scalar() + " is out of the allowed range [" +
                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
    v = static_cast<long>(d);
  }
  if (v < lo || v > hi)
    throw ConfigError((on ? where(n) : where(node_)) + ": " + key_path(key) + " = " + std::to_string(v) +
                      " is out of the allowed range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  resolved_here_[key] = v;
  return v;
}

bool MapReader::boolean(const std::string& key, bool default_value, const std::string& meaning) {
  note(key, "boolean", default_value ? "true" : "false", "true, false", "", meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  bool v = default_value;
  if (on) {
    const std::string s = n.IsScalar() ? n.Scalar() : "";
    if (s == "true" || s == "yes" || s == "on") v = true;
    else if (s == "false" || s == "no" || s == "off") v = false;
    else throw ConfigError(where(n) + ": " + key_path(key) + " = '" + s + "' must be true or false");
  }
  resolved_here_[key] = v;
  return v;
}

std::string MapReader::string(const std::string& key, const std::string& default_value, const std::string& meaning) {
  note(key, "text", default_value.empty() ? "\"\"" : default_value, "", "", meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  if (on && !n.IsScalar()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a string");
  std::string v = on ? n.Scalar() : default_value;
  resolved_here_[key] = v;
  return v;
}

std::string MapReader::choice(const std::string& key, const std::string& default_value,
                              const std::vector<std::string>& allowed, const std::string& meaning) {
  std::string words;
  for (const auto& a : allowed) words += (words.empty() ? "" : ", ") + a;
  note(key, "choice", default_value, words, "", meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  if (on && !n.IsScalar()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected one word");
  std::string v = on ? n.Scalar() : default_value;
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw ConfigError((on ? where(n) : where(node_)) + ": " + key_path(key) + " = '" + v +
                      "' is not one of {" + list + "}");
  }
  resolved_here_[key] = v;
  return v;
}

std::vector<double> MapReader::numbers(const std::string& key, const std::vector<double>& default_value,
                                       Range range, const std::string& unit, const std::string& meaning) {
  std::string listed;
  for (double x : default_value) listed += (listed.empty() ? "" : ", ") + fmt(x);
  note(key, "list of numbers", "[" + listed + "]", "each in " + range.describe(), unit, meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  std::vector<double> v = default_value;
  if (on) {
    if (!n.IsSequence()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a list of numbers");
    v.clear();
    for (std::size_t i = 0; i < n.size(); ++i) {
      double x = to_number(key + "[" + std::to_string(i) + "]", n[i]);
      if (!range.contains(x))
        throw ConfigError(where(n[i]) + ": " + key_path(key) + "[" + std::to_string(i) + "] = " + fmt(x) +
                          " is out of the allowed range " + range.describe() + (unit.empty() ? "" : " " + unit));
      v.push_back(x);
    }
  }
  YAML::Node seq(YAML::NodeType::Sequence);
  for (double x : v) seq.push_back(fmt(x));
  seq.SetStyle(YAML::EmitterStyle::Flow);
  resolved_here_[key] = seq;
  return v;
}

std::array<double, 3> MapReader::vec3(const std::string& key, const std::array<double, 3>& default_value,
                                      const std::string& unit, const std::string& meaning) {
  note(key, "3-vector", "[" + fmt(default_value[0]) + ", " + fmt(default_value[1]) + ", " + fmt(default_value[2]) + "]",
       "", unit, meaning);
  std::vector<double> d(default_value.begin(), default_value.end());
  const YAML::Node& self = node_;
  YAML::Node n = self.IsMap() ? self[key] : YAML::Node();
  if (n.IsDefined() && n.IsSequence() && n.size() != 3)
    throw ConfigError(where(n) + ": " + key_path(key) + " has " + std::to_string(n.size()) +
                      " components; a vector needs 3" + (unit.empty() ? "" : " (" + unit + ")"));
  std::vector<double> v = numbers(key, d, Range::any(), unit);
  return {v[0], v[1], v[2]};
}

MapReader MapReader::child(const std::string& key, const std::string& meaning) {
  note(key, "section", "", "", "", meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  if (on && !n.IsMap()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a mapping (key: value)");
  YAML::Node r = resolved_here_[key];
  if (!r.IsMap()) {
    resolved_here_[key] = YAML::Node(YAML::NodeType::Map);
    r = resolved_here_[key];
  }
  return MapReader(on ? n : YAML::Node(YAML::NodeType::Map), key_path(key), shared_, r);
}

std::vector<MapReader> MapReader::children(const std::string& key, const std::string& meaning) {
  note(key, "list of sections", "[]", "", "", meaning);
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  std::vector<MapReader> out;
  if (!on) return out;
  if (!n.IsSequence()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a list of mappings");
  resolved_here_[key] = YAML::Node(YAML::NodeType::Sequence);
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap())
      throw ConfigError(where(n[i]) + ": " + key_path(key) + "[" + std::to_string(i) + "]: expected a mapping");
    YAML::Node r(YAML::NodeType::Map);
    resolved_here_[key].push_back(r);
    out.push_back(MapReader(n[i], key_path(key) + "[" + std::to_string(i) + "]", shared_,
                            resolved_here_[key][i]));
  }
  return out;
}

void MapReader::known_keys(const std::vector<std::string>& keys) {
  known_.insert(known_.end(), keys.begin(), keys.end());
  check_keys(known_);
}

void MapReader::check_keys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) return;
  std::vector<std::string> known;
  for (const auto& u : allowed)
    if (std::find(known.begin(), known.end(), u) == known.end()) known.push_back(u);
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.Scalar();
    if (std::find(known.begin(), known.end(), k) != known.end()) continue;
    std::string list;
    for (const auto& u : known) list += (list.empty() ? "" : ", ") + u;
    const std::string near = closest_word(k, known);
    throw ConfigError(where(it->first) + ": unknown key '" + key_path(k) + "'" +
                      (near.empty() ? "" : " (did you mean '" + near + "'?)") + "; known keys here: " + list);
  }
}

void MapReader::finish() const {
  std::vector<std::string> allowed = used_;
  allowed.insert(allowed.end(), known_.begin(), known_.end());
  check_keys(allowed);
}

std::string MapReader::resolved_text() const {
  YAML::Emitter e;
  e << shared_->resolved;
  return e.c_str();
}

}  // namespace centrec::config
