#include "bench/bench_table.hpp"

#include <cstdio>
#include <map>
#include <stdexcept>

namespace centrec::bench {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
std::string sci(const EngineResult& r, double v) { return r.ok ? fmt("%.3g", v) : "-"; }
std::string fix2(const EngineResult& r, double v) { return r.ok ? fmt("%.2f", v) : "-"; }
double contacts_per_particle(const EngineResult& r) {
  return r.particles ? 2.0 * r.final.pair_contacts / r.particles : 0.0;
}
double wall_per_particle(const EngineResult& r) { return r.particles ? r.final.wall_contacts / r.particles : 0.0; }
double cost(const EngineResult& r) {  // seconds per particle-step
  const double s = r.particle_steps_per_second();
  return s > 0 ? 1.0 / s : 0.0;
}

// Cost relative to the first (smallest N) row with the same worker count.
std::map<int, const BenchRow*> first_rows(const std::vector<BenchRow>& rows) {
  std::map<int, const BenchRow*> first;
  for (const auto& r : rows)
    if (!first.count(r.workers) || r.particles < first[r.workers]->particles) first[r.workers] = &r;
  return first;
}
std::string relative_cost(const EngineResult& r, const EngineResult& base) {
  return r.ok && base.ok && cost(base) > 0 ? fmt("%.2f", cost(r) / cost(base)) : "-";
}
std::string spread(const EngineResult& r) {
  if (!r.ok || r.seconds.empty()) return "-";
  double lo = r.seconds[0], hi = r.seconds[0];
  for (double s : r.seconds) lo = std::min(lo, s), hi = std::max(hi, s);
  return fmt("%.3f", lo) + "-" + fmt("%.3f", hi);
}

std::vector<const EngineResult*> engines(const BenchRow& row) { return {&row.centrec, &row.liggghts, &row.lammps}; }

void state_row(std::string& md, const FilmCase& fc, const BenchRow& row, const EngineResult& r, const char* when,
               const FilmSummary& s) {
  if (!r.ok && s.atoms == 0) return;
  char b[512];
  std::snprintf(b, sizeof b, "| %ld | %d | %s | %s | %ld | %.4g | %.4g | %.4g | %.5f | %.3f | %.2f | %.4f | %.2f | %.3f |\n",
                row.particles, row.workers, r.engine.c_str(), when, s.atoms, s.kinetic_energy, s.rotational_energy,
                s.mean_speed, s.mean_omega_z, (fc.drum_radius - s.min_radius) / fc.diameter,
                (s.max_radius + 0.5 * fc.diameter - fc.drum_radius) * 1e6, s.mean_vz,
                s.atoms ? 2.0 * s.pair_contacts / s.atoms : 0.0, s.atoms ? s.wall_contacts / s.atoms : 0.0);
  md += b;
}

}  // namespace

std::string format_markdown(const FilmCase& fc, const std::vector<BenchRow>& rows, const std::string& preamble) {
  const auto first = first_rows(rows);
  std::string md = preamble;
  md +=
      "\n| N | threads/ranks | centrec p-steps/s | LIGGGHTS p-steps/s | LAMMPS p-steps/s | centrec / LIGGGHTS "
      "| centrec / LAMMPS | per core c / L / M | contacts/particle c / L / M | wall contacts/particle c / L / M "
      "| bytes/particle c / L / M | cost/particle vs smallest N c / L / M | timed phase s, min-max c / L / M "
      "| list pairs/particle c / L / M | rebuilds/phase c / L / M |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : rows) {
    const BenchRow& base = *first.at(row.workers);
    const EngineResult* e[3] = {&row.centrec, &row.liggghts, &row.lammps};
    const EngineResult* b[3] = {&base.centrec, &base.liggghts, &base.lammps};
    // "c / L / M" of one quantity.
    auto each = [&](auto cell) {
      std::string s;
      for (int k = 0; k < 3; ++k) s += (k ? " / " : "") + cell(*e[k], *b[k]);
      return s;
    };
    auto ratio = [&](const EngineResult& peer) {
      const double pc = row.centrec.particle_steps_per_second(), pp = peer.particle_steps_per_second();
      return row.centrec.ok && peer.ok && pp > 0 ? fmt("%.2f", pc / pp) : std::string("-");
    };
    md += "| " + std::to_string(row.particles) + " | " + std::to_string(row.workers) + " | " +
          sci(row.centrec, row.centrec.particle_steps_per_second()) + " | " +
          sci(row.liggghts, row.liggghts.particle_steps_per_second()) + " | " +
          sci(row.lammps, row.lammps.particle_steps_per_second()) + " | " + ratio(row.liggghts) + " | " +
          ratio(row.lammps) + " | " +
          each([&](const EngineResult& r, const EngineResult&) { return sci(r, r.particle_steps_per_second() / row.workers); }) +
          " | " + each([](const EngineResult& r, const EngineResult&) { return fix2(r, contacts_per_particle(r)); }) +
          " | " + each([](const EngineResult& r, const EngineResult&) { return fix2(r, wall_per_particle(r)); }) +
          " | " +
          each([](const EngineResult& r, const EngineResult&) { return r.ok ? fmt("%.0f", r.bytes_per_particle) : "-"; }) +
          " | " + each([](const EngineResult& r, const EngineResult& b) { return relative_cost(r, b); }) + " | " +
          each([](const EngineResult& r, const EngineResult&) { return spread(r); }) + " | " +
          each([](const EngineResult& r, const EngineResult&) { return fix2(r, r.list_pairs_per_particle); }) + " | " +
          each([](const EngineResult& r, const EngineResult&) { return fix2(r, r.rebuilds_per_phase); }) + " |\n";
  }
  md +=
      "\nFilm state reached by each engine (same initial file; contacts per particle = 2 x overlapping pairs / N; "
      "wall = centres within d/2 of the analytic cylinder; thickness = (R - innermost centre)/d; deepest wall "
      "overlap = outermost centre + d/2 - R, small and positive while the wall holds every particle):\n\n"
      "| N | threads/ranks | engine | when | atoms | KE J | rot. KE J | mean speed m/s | mean omega_z rad/s "
      "| thickness d | deepest wall overlap um | mean vz m/s | contacts/particle | wall/particle |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : rows) {
    for (const EngineResult* r : engines(row)) {
      state_row(md, fc, row, *r, "settled", r->settled);
      state_row(md, fc, row, *r, "final", r->final);
    }
  }
  std::string notes;
  for (const auto& row : rows)
    for (const EngineResult* r : engines(row))
      if (!r->note.empty()) notes += "- N " + std::to_string(row.particles) + ", " + std::to_string(row.workers) +
                                     " workers: " + r->note + "\n";
  if (!notes.empty()) md += "\nProblems:\n" + notes;
  return md;
}

void write_csv(const std::string& path, const std::vector<BenchRow>& rows) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f,
               "engine,particles,workers,steps,median_s,particle_steps_per_s,per_core,contacts_per_particle,"
               "wall_contacts_per_particle,bytes_per_particle,rss_bytes_per_particle,list_pairs_per_particle,"
               "rebuilds_per_phase,final_ke,final_mean_speed,final_mean_omega_z,ok,seconds\n");
  for (const auto& row : rows)
    for (const EngineResult* r : engines(row)) {
      if (r->engine.empty()) continue;
      std::string secs;
      for (double s : r->seconds) secs += (secs.empty() ? "" : ";") + fmt("%.6f", s);
      const double p = r->particle_steps_per_second();
      std::fprintf(f, "%s,%ld,%d,%ld,%.6f,%.6g,%.6g,%.4f,%.4f,%.1f,%.1f,%.4f,%.2f,%.6g,%.6g,%.6g,%d,%s\n", r->engine.c_str(),
                   r->particles, r->workers, r->steps, r->median_seconds(), p, p / r->workers,
                   contacts_per_particle(*r), wall_per_particle(*r), r->bytes_per_particle, r->rss_bytes_per_particle,
                   r->list_pairs_per_particle, r->rebuilds_per_phase,
                   r->final.kinetic_energy, r->final.mean_speed, r->final.mean_omega_z, r->ok ? 1 : 0, secs.c_str());
    }
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

void write_text(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fputs(text.c_str(), f);
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

}  // namespace centrec::bench
