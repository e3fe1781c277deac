#include "config/strict_yaml.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace centrec::config {

namespace {
std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
}  // namespace

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
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ConfigError(path + ": cannot open the case file");
  } catch (const YAML::ParserException& e) {
    throw ConfigError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) throw ConfigError(path + ": the case file must be a YAML mapping (key: value)");
  auto shared = std::make_shared<Shared>();
  shared->source = path;
  shared->resolved = YAML::Node(YAML::NodeType::Map);
  return MapReader(root, "", shared, shared->resolved);
}

MapReader MapReader::from_string(const std::string& text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(source_name + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) throw ConfigError(source_name + ": the case must be a YAML mapping (key: value)");
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
  return v;
}

double MapReader::number(const std::string& key, double default_value, Range range, const std::string& unit) {
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

double MapReader::required_number(const std::string& key, Range range, const std::string& unit) {
  if (!has(key)) fail(key, "is required" + (unit.empty() ? std::string() : " (unit " + unit + ")"));
  return number(key, 0.0, range, unit);
}

long MapReader::integer(const std::string& key, long default_value, long lo, long hi) {
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  long v = default_value;
  if (on) {
    double d = to_number(key, n);
    if (d != std::floor(d))
      throw ConfigError(where(n) + ": " + key_path(key) + " = " + n.Scalar() + " must be an integer");
    v = static_cast<long>(d);
  }
  if (v < lo || v > hi)
    throw ConfigError((on ? where(n) : where(node_)) + ": " + key_path(key) + " = " + std::to_string(v) +
                      " is out of the allowed range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  resolved_here_[key] = v;
  return v;
}

bool MapReader::boolean(const std::string& key, bool default_value) {
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

std::string MapReader::string(const std::string& key, const std::string& default_value) {
  const auto on = get(key);
  const YAML::Node n = on ? *on : YAML::Node();
  if (on && !n.IsScalar()) throw ConfigError(where(n) + ": " + key_path(key) + ": expected a string");
  std::string v = on ? n.Scalar() : default_value;
  resolved_here_[key] = v;
  return v;
}

std::string MapReader::choice(const std::string& key, const std::string& default_value,
                              const std::vector<std::string>& allowed) {
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
                                       Range range, const std::string& unit) {
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
                                      const std::string& unit) {
  std::vector<double> d(default_value.begin(), default_value.end());
  const YAML::Node& self = node_;
  YAML::Node n = self.IsMap() ? self[key] : YAML::Node();
  if (n.IsDefined() && n.IsSequence() && n.size() != 3)
    throw ConfigError(where(n) + ": " + key_path(key) + " has " + std::to_string(n.size()) +
                      " components; a vector needs 3" + (unit.empty() ? "" : " (" + unit + ")"));
  std::vector<double> v = numbers(key, d, Range::any(), unit);
  return {v[0], v[1], v[2]};
}

MapReader MapReader::child(const std::string& key) {
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

std::vector<MapReader> MapReader::children(const std::string& key) {
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

void MapReader::finish() const {
  if (!node_.IsMap()) return;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.Scalar();
    if (std::find(used_.begin(), used_.end(), k) == used_.end()) {
      std::string known;
      for (const auto& u : used_) known += (known.empty() ? "" : ", ") + u;
      throw ConfigError(where(it->first) + ": unknown key '" + key_path(k) + "' (known keys here: " + known + ")");
    }
  }
}

std::string MapReader::resolved_text() const {
  YAML::Emitter e;
  e << shared_->resolved;
  return e.c_str();
}

}  // namespace centrec::config
