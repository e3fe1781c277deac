#include "io/checkpoint_h5.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "dem/simulation.hpp"
#include "io/h5_file.hpp"

namespace centrec::io {

namespace {

constexpr const char* kFormat = "centrec-checkpoint-1";

// FNV-1a over everything written, in the order written.
struct Checksum {
  std::uint64_t h = 1469598103934665603ULL;
  void mix(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ULL;
  }
  void mix(const std::string& s) {
    mix(s.data(), s.size());
    mix("\0", 1);
  }
  std::string hex() const {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

// The two directions of one schema (visit() below): the writer stores the values it is
// given, the reader fills them in; both feed the checksum in the same order.
class Writer {
 public:
  explicit Writer(H5File& f) : f_(f) {}
  void array(const std::string& path, std::vector<double>& data, std::size_t cols, const std::string& units) {
    const std::vector<std::size_t> dims = cols == 1 ? std::vector<std::size_t>{data.size()}
                                                    : std::vector<std::size_t>{data.size() / cols, cols};
    sum_.mix(path);
    sum_.mix(data.data(), data.size() * sizeof(double));
    f_.write(path, data, dims, units);
  }
  void text(const std::string& obj, const std::string& name, std::string& value) {
    sum_.mix(obj + "@" + name);
    sum_.mix(value);
    f_.create_group(obj);
    f_.set_attribute(obj, name, value);
  }
  void number(const std::string& obj, const std::string& name, double& value) {
    sum_.mix(obj + "@" + name);
    sum_.mix(&value, sizeof value);
    f_.create_group(obj);
    f_.set_attribute(obj, name, value);
  }
  static constexpr bool reading = false;
  Checksum sum_;

 private:
  H5File& f_;
};

class Reader {
 public:
  explicit Reader(const H5File& f) : f_(f) {}
  void array(const std::string& path, std::vector<double>& data, std::size_t cols, const std::string&) {
    std::vector<std::size_t> dims;
    data = f_.read(path, &dims);
    const std::size_t got = dims.size() == 2 ? dims[1] : 1;
    if (got != cols) throw std::runtime_error("dataset " + path + " has " + std::to_string(got) + " columns, not " + std::to_string(cols));
    sum_.mix(path);
    sum_.mix(data.data(), data.size() * sizeof(double));
  }
  void text(const std::string& obj, const std::string& name, std::string& value) {
    value = f_.string_attribute(obj, name);
    sum_.mix(obj + "@" + name);
    sum_.mix(value);
  }
  void number(const std::string& obj, const std::string& name, double& value) {
    value = f_.number_attribute(obj, name);
    sum_.mix(obj + "@" + name);
    sum_.mix(&value, sizeof value);
  }
  bool has(const std::string& obj, const std::string& name) const { return f_.has_attribute(obj, name); }
  static constexpr bool reading = true;
  Checksum sum_;

 private:
  const H5File& f_;
};

// Integer-valued numbers travel as doubles (exact below 2^53).
template <class IO, class T>
void integer(IO& io, const std::string& obj, const std::string& name, T& value) {
  double d = static_cast<double>(value);
  io.number(obj, name, d);
  if (IO::reading) value = static_cast<T>(static_cast<long long>(d));
}

// A vector of records as an n x cols array: `to` flattens one record, `from` rebuilds it.
template <class IO, class T, class To, class From>
void records(IO& io, const std::string& path, std::vector<T>& v, std::size_t cols, const std::string& units, To to,
             From from) {
  std::vector<double> flat;
  if (!IO::reading) {
    flat.reserve(v.size() * cols);
    for (const T& r : v) to(r, flat);
  }
  io.array(path, flat, cols, units);
  if (IO::reading) {
    v.assign(flat.size() / cols, T{});
    for (std::size_t i = 0; i < v.size(); ++i) from(&flat[i * cols], v[i]);
  }
}

template <class IO>
void vec3s(IO& io, const std::string& path, std::vector<dem::Vec3>& v, const std::string& units) {
  records(io, path, v, 3, units, [](const dem::Vec3& a, std::vector<double>& o) { o.insert(o.end(), {a.x, a.y, a.z}); },
          [](const double* p, dem::Vec3& a) { a = {p[0], p[1], p[2]}; });
}

template <class IO, class T>
void integers(IO& io, const std::string& path, std::vector<T>& v, const std::string& units = "1") {
  records(io, path, v, 1, units, [](const T& a, std::vector<double>& o) { o.push_back(static_cast<double>(a)); },
          [](const double* p, T& a) { a = static_cast<T>(static_cast<long long>(p[0])); });
}

template <class IO>
void doubles(IO& io, const std::string& path, std::vector<double>& v, const std::string& units) {
  records(io, path, v, 1, units, [](double a, std::vector<double>& o) { o.push_back(a); },
          [](const double* p, double& a) { a = p[0]; });
}

template <class IO>
void histories(IO& io, const std::string& path, std::vector<dem::ContactHistory>& v) {
  records(io, path, v, 6, dem::kContactHistoryUnits,
          [](const dem::ContactHistory& h, std::vector<double>& o) {
            o.insert(o.end(), {h.shear.x, h.shear.y, h.shear.z, h.roll.x, h.roll.y, h.roll.z});
          },
          [](const double* p, dem::ContactHistory& h) { h = {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}}; });
}

template <class IO>
void visit_engine(IO& io, dem::SimulationState& s) {
  const std::string g = "/engine";
  io.number(g, "time", s.time);
  integer(io, g, "step", s.step);
  io.number(g, "dt", s.dt);
  integer(io, g, "next_id", s.next_id);
  io.number(g, "drum_angle", s.drum_angle);
  records(io, g + "/materials", s.materials, 3, "Pa, 1, kg/m3",
          [](const dem::Material& m, std::vector<double>& o) { o.insert(o.end(), {m.youngs_modulus, m.poisson_ratio, m.density}); },
          [](const double* p, dem::Material& m) { m = {p[0], p[1], p[2]}; });
  // The pair interactions: their numeric fields as columns, their rolling models by name
  // with the model's own coefficients (an attribute, "epsd2 sds:100:0.5", each coefficient
  // written exactly; a checkpoint without it was written when EPSD2 was the only model).
  std::size_t numeric = 0;
  dem::for_each_pair_field([&](const char*, auto, double, double, bool, const char*) { ++numeric; },
                           [](const char*, auto, auto) {});
  records(io, g + "/interactions", s.interactions, numeric, "1",
          [](const dem::PairInteraction& m, std::vector<double>& o) {
            dem::for_each_pair_field([&](const char*, auto f, double, double, bool, const char*) { o.push_back(m.*f); },
                                     [](const char*, auto, auto) {});
          },
          [](const double* p, dem::PairInteraction& m) {
            dem::for_each_pair_field([&](const char*, auto f, double, double, bool, const char*) { m.*f = *p++; },
                                     [](const char*, auto, auto) {});
          });
  std::string models;
  if constexpr (IO::reading) {
    if (io.has(g, "interaction_rolling_models")) {
      io.text(g, "interaction_rolling_models", models);
      std::istringstream names(models);
      std::string word;
      for (dem::PairInteraction& m : s.interactions) {
        bool ok = static_cast<bool>(names >> word);
        std::istringstream parts(word);
        std::string name;
        ok = ok && std::getline(parts, name, ':') && dem::rolling_model_named(name, m.rolling_model);
        m.rolling_coefficients = {};
        if (ok)
          dem::for_each_rolling_coefficient(m.rolling_model, [&](std::size_t k, const dem::RollingCoefficient&) {
            std::string v;
            char* end = nullptr;
            ok = ok && std::getline(parts, v, ':') && !v.empty();
            if (ok) m.rolling_coefficients[k] = std::strtod(v.c_str(), &end);
            ok = ok && end == v.c_str() + v.size();
          });
        if (!ok || parts.peek() != EOF)
          throw std::runtime_error("checkpoint: interaction_rolling_models \"" + models +
                                   "\" does not name a rolling model with its coefficients for each interaction");
      }
    }
  } else {
    for (const dem::PairInteraction& m : s.interactions) {
      models += std::string(models.empty() ? "" : " ") + dem::rolling_model_info(m.rolling_model).name;
      dem::for_each_rolling_coefficient(m.rolling_model, [&](std::size_t k, const dem::RollingCoefficient&) {
        char b[32];
        std::snprintf(b, sizeof b, ":%.17g", m.rolling_coefficients[k]);
        models += b;
      });
    }
    io.text(g, "interaction_rolling_models", models);
  }
  vec3s(io, g + "/wall_origins", s.wall_origins, "m");
  vec3s(io, g + "/wall_force", s.wall_force, "N");
  // The per-particle arrays, as the engine lists them (id, material, ..., wall_history).
  dem::Simulation::for_each_state_particle_array(s, [&](const char* name, const char* units, auto& array) {
    using T = typename std::decay_t<decltype(array)>::value_type;
    const std::string path = g + "/" + name;
    if constexpr (std::is_same_v<T, dem::Vec3>)
      vec3s(io, path, array, units);
    else if constexpr (std::is_same_v<T, double>)
      doubles(io, path, array, units);
    else if constexpr (std::is_same_v<T, dem::ContactHistory>)
      histories(io, path, array);
    else
      integers(io, path, array, units);
  });
  std::vector<dem::ContactHistory> h;
  std::vector<std::int64_t> ids;
  if (!IO::reading)
    for (const auto& p : s.pair_history) {
      ids.insert(ids.end(), {p.id_lo, p.id_hi});
      h.push_back(p.history);
    }
  integers(io, g + "/pair_ids", ids);
  histories(io, g + "/pair_history", h);
  if (IO::reading) {
    if (ids.size() != 2 * h.size()) throw std::runtime_error("pair_ids and pair_history lengths differ");
    s.pair_history.resize(h.size());
    for (std::size_t k = 0; k < h.size(); ++k) s.pair_history[k] = {ids[2 * k], ids[2 * k + 1], h[k]};
  }
}

template <class IO>
void visit_scene(IO& io, dem::scene::SceneState& s) {
  visit_engine(io, s.engine);
  const std::string g = "/scene";
  io.number(g, "out_total", s.out_total);
  io.number(g, "lost_total", s.lost_total);
  integer(io, g, "has_feeder", s.has_feeder);
  records(io, g + "/mass_flow_log", s.mass_flow_log, 7,
          "s, kg, kg, kg, kg, 1, kg/s (time fed out lost holdup particles axial_flow)",
          [](const dem::scene::MassFlowSample& m, std::vector<double>& o) {
            o.insert(o.end(), {m.time, m.fed, m.out, m.lost, m.holdup, static_cast<double>(m.particles), m.axial_flow});
          },
          [](const double* p, dem::scene::MassFlowSample& m) {
            m = {p[0], p[1], p[2], p[3], p[4], static_cast<std::int64_t>(p[5]), p[6]};
          });
  integer(io, g, "has_controller", s.has_controller);
  if (s.has_controller) {
    const std::string c = "/controller";
    auto& cs = s.controller;
    io.number(c, "window_start", cs.window_start);
    io.number(c, "flow_sum", cs.flow_sum);
    integer(io, c, "flow_samples", cs.flow_samples);
    io.text(c, "rng", cs.rng);
    io.text(c, "size_rng", cs.size_rng);
    records(io, c + "/log", cs.log, 4, "s, kg/s, 1, 1 (time mass_flow particles change)",
            [](const dem::scene::ControllerWindow& w, std::vector<double>& o) {
              o.insert(o.end(), {w.time, w.mass_flow, static_cast<double>(w.particles), static_cast<double>(w.change)});
            },
            [](const double* p, dem::scene::ControllerWindow& w) {
              w = {p[0], p[1], static_cast<std::int64_t>(p[2]), static_cast<std::int64_t>(p[3])};
            });
  }
  if (!s.has_feeder) return;
  const std::string f = "/feeder";
  io.text(f, "size_rng", s.feeder.size_rng);
  io.text(f, "place_rng", s.feeder.place_rng);
  io.number(f, "backlog", s.feeder.backlog);
  io.number(f, "next_diameter", s.feeder.next_diameter);
  io.number(f, "inserted_mass", s.feeder.stats.inserted_mass);
  integer(io, f, "inserted", s.feeder.stats.inserted);
  integer(io, f, "deferred", s.feeder.stats.deferred);
  io.number(f, "requested_mass", s.feeder.stats.requested_mass);
}

template <class IO>
void visit_snapshot(IO& io, const std::string& g, film::ParticleColumns& c) {
  io.number(g, "time", c.time);
  auto col = [&](const char* name, std::vector<double>& v, const char* units) { doubles(io, g + "/" + name, v, units); };
  col("x", c.x, "m");
  col("y", c.y, "m");
  col("z", c.z, "m");
  col("vx", c.vx, "m/s");
  col("vy", c.vy, "m/s");
  col("vz", c.vz, "m/s");
  col("radius", c.radius, "m");
  integers(io, g + "/id", c.id);
}

template <class IO>
void visit(IO& io, RunCheckpoint& c) {
  io.text("/", "code_version", c.code_version);
  io.text("/", "case_path", c.case_path);
  io.text("/", "resolved_config", c.resolved_yaml);
  io.text("/", "phase", c.phase);
  integer(io, "/", "sampled_turns", c.sampled_turns);
  // A checkpoint written only at the end of turns (an older file) has no turn_snapshots: 0.
  if constexpr (IO::reading) {
    if (io.has("/", "turn_snapshots")) integer(io, "/", "turn_snapshots", c.turn_snapshots);
  } else {
    integer(io, "/", "turn_snapshots", c.turn_snapshots);
  }
  io.number("/", "particle_steps", c.particle_steps);
  io.number("/", "wall_time_s", c.wall_time);
  visit_scene(io, c.scene);
  // Sampler arrays: their names first, then each array.
  std::string names;
  for (const auto& [k, v] : c.sampler) names += k + "\n";
  io.text("/", "sampler_arrays", names);
  if (IO::reading) {
    c.sampler.clear();
    for (std::size_t a = 0, b; (b = names.find('\n', a)) != std::string::npos; a = b + 1) c.sampler[names.substr(a, b - a)];
  }
  for (auto& [k, v] : c.sampler) io.array("/sampler/" + k, v, 1, "1");
  bool has_snapshot = c.start_snapshot.has_value();
  integer(io, "/", "has_start_snapshot", has_snapshot);
  if (IO::reading && has_snapshot) c.start_snapshot.emplace();
  if (has_snapshot) visit_snapshot(io, "/start_snapshot", *c.start_snapshot);
}

}  // namespace

std::string checkpoint_path(const std::string& dir) { return dir + "/checkpoint.h5"; }

void write_checkpoint(const std::string& dir, const RunCheckpoint& c) {
  H5File f = H5File::create(checkpoint_path(dir));
  f.set_attribute("/", "format", kFormat);
  Writer w(f);
  RunCheckpoint copy = c;  // visit() takes references for both directions
  visit(w, copy);
  f.set_attribute("/", "checksum", w.sum_.hex());
  f.commit();
}

RunCheckpoint read_checkpoint(const std::string& dir) {
  const std::string path = checkpoint_path(dir);
  try {
    const H5File f = H5File::open_read(path);
    if (!f.has_attribute("/", "format") || f.string_attribute("/", "format") != kFormat)
      throw std::runtime_error(std::string("not a ") + kFormat + " file");
    RunCheckpoint c;
    Reader r(f);
    visit(r, c);
    const std::string stored = f.string_attribute("/", "checksum");
    if (stored != r.sum_.hex())
      throw std::runtime_error("checksum mismatch (stored " + stored + ", computed " + r.sum_.hex() +
                               "): the file is damaged");
    return c;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot resume from " + path + ": " + e.what());
  }
}

}  // namespace centrec::io
