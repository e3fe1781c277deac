#include "bench/liggghts_log.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "liggghts/liggghts_log_reader.hpp"

namespace centrec::bench {
namespace {

const char* const kLammpsMemory = "Per MPI rank memory allocation (min/avg/max) = ";
const char* const kOutputRow = "Output  |";

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

// "BENCH_STATE tag key value key value ..." -> summary.
FilmSummary parse_state(std::istringstream& in) {
  std::map<std::string, double> kv;
  std::string key;
  double value;
  while (in >> key >> value) kv[key] = value;
  FilmSummary s;
  s.atoms = static_cast<long>(kv["atoms"]);
  s.kinetic_energy = kv["ke"];
  s.rotational_energy = kv["rke"];
  s.mean_speed = kv["mean_speed"];
  s.mean_omega_z = kv["mean_omega_z"];
  s.min_radius = kv["min_r"];
  s.max_radius = kv["max_r"];
  s.mean_vz = kv["mean_vz"];
  s.pair_contacts = kv["pair_contacts"];
  s.wall_contacts = kv["wall_contacts"];
  return s;
}

}  // namespace

LiggghtsLog parse_liggghts_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read LIGGGHTS log " + path);
  LiggghtsLog log;
  std::string line, phase;
  while (std::getline(in, line)) {
    if (starts_with(line, "BENCH_PHASE ")) {
      phase = line.substr(12);
    } else if (starts_with(line, "BENCH_STATE ")) {
      std::istringstream l(line.substr(12));
      std::string tag;
      l >> tag;
      if (tag == "settled") log.settled = parse_state(l), log.have_settled = true;
      if (tag == "final") log.final = parse_state(l), log.have_final = true;
    } else if (starts_with(line, "Memory usage per processor =")) {
      // LIGGGHTS' estimate grows as its neighbour pages fill: keep the largest seen in
      // the timed runs.
      if (starts_with(phase, "timed"))
        log.memory_mbytes_per_rank = std::max(log.memory_mbytes_per_rank, std::stod(line.substr(28)));
    } else if (starts_with(line, kLammpsMemory)) {
      // LAMMPS: "= min | avg | max Mbytes"; the deck's later runs skip the set-up that prints it.
      std::istringstream l(line.substr(std::string(kLammpsMemory).size()));
      double lo = 0, avg = 0;
      std::string bar;
      if (l >> lo >> bar >> avg) log.memory_mbytes_per_rank = std::max(log.memory_mbytes_per_rank, avg);
    } else if (starts_with(line, kOutputRow)) {
      // Timing breakdown row "Output  | min | avg | max | %varavg | %total".
      if (starts_with(phase, "timed")) {
        std::istringstream l(line.substr(std::string(kOutputRow).size()));
        double lo = 0, avg = 0;
        std::string bar;
        if (l >> lo >> bar >> avg) log.timed_output_seconds.push_back(avg);
      }
    } else if (starts_with(line, "Loop time of ")) {
      if (starts_with(phase, "timed")) {
        liggghts::LiggghtsLoopTime t;
        if (!liggghts::parse_loop_time(line, t)) throw std::runtime_error("cannot parse LIGGGHTS line: " + line);
        log.timed_loop_seconds.push_back(t.seconds);
        log.timed_loop_steps.push_back(t.steps);
        log.atoms_in_loop = t.atoms;
      }
    } else if (starts_with(line, "Ave neighs/atom = ")) {
      // Half list (newton off: pairs across a rank boundary are held by both ranks).
      if (starts_with(phase, "timed")) log.neighs_per_atom = std::stod(line.substr(18));
    } else if (starts_with(line, "Neighbor list builds = ")) {
      const long builds = std::stol(line.substr(23));
      if (starts_with(phase, "timed")) log.timed_rebuilds += builds, log.last_timed_rebuilds = builds;
      if (phase == "settle") log.settle_rebuilds = builds;
    } else if (log.error.empty() && line.find("ERROR") != std::string::npos) {
      log.error = line;
    }
  }
  return log;
}

}  // namespace centrec::bench
