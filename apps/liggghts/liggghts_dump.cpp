#include "liggghts/liggghts_dump.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace centrec::liggghts {

namespace {

[[noreturn]] void fail(const std::string& path, long line, const std::string& what) {
  throw std::runtime_error(path + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

dem::scene::SnapshotArrays read_liggghts_dump(const std::string& path, double dt) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read LIGGGHTS dump " + path);
  dem::scene::SnapshotArrays s;
  std::string line;
  long ln = 0, step = -1, atoms = -1;
  auto next = [&]() -> bool {
    if (!std::getline(in, line)) return false;
    ++ln;
    return true;
  };
  while (next()) {
    if (line.rfind("ITEM: TIMESTEP", 0) == 0) {
      if (!next()) fail(path, ln, "missing timestep");
      step = std::stol(line);
    } else if (line.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
      if (!next()) fail(path, ln, "missing atom count");
      atoms = std::stol(line);
    } else if (line.rfind("ITEM: ATOMS", 0) == 0) {
      if (step < 0 || atoms < 0) fail(path, ln, "ATOMS before TIMESTEP / NUMBER OF ATOMS");
      std::istringstream h(line.substr(11));
      std::map<std::string, std::size_t> col;
      std::string name;
      for (std::size_t k = 0; h >> name; ++k) col[name] = k;
      std::vector<std::size_t> idx;
      for (const char* c : {"id", "radius", "x", "y", "z", "vx", "vy", "vz"}) {
        const auto it = col.find(c);
        if (it == col.end()) fail(path, ln, std::string("no column '") + c + "' in: " + line);
        idx.push_back(it->second);
      }
      for (auto* v : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.radius}) v->reserve(static_cast<std::size_t>(atoms));
      std::vector<double> f(col.size());
      for (long a = 0; a < atoms; ++a) {
        if (!next()) fail(path, ln, "truncated: " + std::to_string(a) + " of " + std::to_string(atoms) + " atoms");
        std::istringstream r(line);
        for (double& x : f) r >> x;
        if (!r) fail(path, ln, "expected " + std::to_string(f.size()) + " numbers: " + line);
        s.id.push_back(static_cast<std::int64_t>(f[idx[0]]));
        s.radius.push_back(f[idx[1]]);
        s.x.push_back(f[idx[2]]);
        s.y.push_back(f[idx[3]]);
        s.z.push_back(f[idx[4]]);
        s.vx.push_back(f[idx[5]]);
        s.vy.push_back(f[idx[6]]);
        s.vz.push_back(f[idx[7]]);
      }
      s.time = static_cast<double>(step) * dt;
      return s;
    }
  }
  fail(path, ln, "no ITEM: ATOMS section");
}

std::int64_t dump_file_step(const std::string& file_name) {
  std::size_t k = file_name.find_last_of("0123456789");
  if (k == std::string::npos) return -1;
  std::size_t b = k;
  while (b > 0 && std::isdigit(static_cast<unsigned char>(file_name[b - 1]))) --b;
  return std::stoll(file_name.substr(b, k - b + 1));
}

std::vector<std::string> list_dump_files(const std::string& dir, const std::string& prefix,
                                         const std::string& suffix) {
  std::vector<std::pair<std::int64_t, std::string>> found;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n.size() <= prefix.size() + suffix.size() || n.rfind(prefix, 0) != 0 ||
        n.compare(n.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    found.push_back({dump_file_step(n), e.path().string()});
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

}  // namespace centrec::liggghts
