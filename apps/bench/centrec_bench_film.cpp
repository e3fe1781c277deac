// centrec_bench_film: Times centrec, LIGGGHTS 3.8 and LAMMPS on the same settled
// particle film in the D12 drum at several N and thread/rank counts; see --help.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "liggghts/liggghts_stl.hpp"
#include "bench/bench_options.hpp"
#include "bench/bench_table.hpp"
#include "bench/centrec_run.hpp"
#include "bench/film_case.hpp"
#include "bench/film_initial_state.hpp"
#include "bench/lammps_deck.hpp"
#include "bench/lammps_run.hpp"
#include "bench/liggghts_deck.hpp"
#include "bench/liggghts_run.hpp"

namespace fs = std::filesystem;
using namespace centrec::bench;

namespace {

void print_result(const EngineResult& r) {
  if (r.ok)
    std::printf("  %-8s %d worker(s): median %.3f s per %ld steps -> %.3g particle-steps/s; final KE %.4g J, "
                "mean |v| %.4f m/s, mean omega_z %.4f rad/s, %ld particles\n",
                r.engine.c_str(), r.workers, r.median_seconds(), r.steps, r.particle_steps_per_second(),
                r.final.kinetic_energy, r.final.mean_speed, r.final.mean_omega_z, r.final.atoms);
  else
    std::printf("  %-8s %d worker(s): FAILED: %s\n", r.engine.c_str(), r.workers, r.note.c_str());
  std::fflush(stdout);
}

std::string preamble(const FilmCase& c, const BenchOptions& o) {
  char phase[256];
  if (o.phase_particle_steps > 0)
    std::snprintf(phase, sizeof phase, "%.3g particle-steps (steps = that / N, see the csv)", o.phase_particle_steps);
  else if (o.replay_particle_steps > 0)
    std::snprintf(phase, sizeof phase,
                  "%ld steps at every N (the same film window); centrec replays the window from the settled "
                  "state until it has timed about %.3g particle-steps (phases per N in the csv)",
                  o.steps, o.replay_particle_steps);
  else
    std::snprintf(phase, sizeof phase, "%ld steps", o.steps);
  char b[4096];
  const std::time_t now = std::time(nullptr);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  const LammpsLaw law = lammps_law(c);
  std::snprintf(b, sizeof b,
                "# centrec vs LIGGGHTS 3.8 and LAMMPS: settled film in the D12 drum\n\n"
                "%s, %u hardware threads. Case: D = %.3g m, %.2f rpm (omega %.4f rad/s), gravity %.2f m/s^2 at %.0f deg "
                "to the axis, periodic in z; d = %.3g m, rho = %.0f, E = %.3g Pa, nu = %.2f, e = %.2f, mu = %.2f, "
                "mu_r = %.2f, wall mu = %.0f, wall mu_r = %.2f; dt = %.3g s; %d lattice layers. Timed phase: %s "
                "after %ld settle steps, median of the repeats. LIGGGHTS: skin %.2f d, STL %d facets around. centrec: "
                "skin %.2f d, wall rolling in LIGGGHTS form.\n\n"
                "LAMMPS (pair_style granular, fix wall/gran/region on a cylinder region rotating at omega): skin "
                "%.2f d; hertz/material with the Tsuji dashpot at alpha = %.4f (parameter %.4f; LIGGGHTS' dashpot, "
                "restitution %.2f), Mindlin k_t = 8 G* a with xgammat %.4f (LIGGGHTS' tangential dashpot); phase times "
                "without LAMMPS' Output timer (its state computes ride in every run's last-step thermo). Where its law "
                "differs: rolling SDS has a constant stiffness (k_roll %.4g N/m pair, %.4g N/m wall: EPSD2's k_t R*^2 "
                "at overlaps %.1e d and %.1e d) where EPSD2's grows with sqrt(overlap); its tangential and rolling "
                "caps include the dashpot, and history is rotated into the tangent plane keeping its length; the "
                "wall is an analytic rotating cylinder (coefficients scaled from LAMMPS' R_eff = %.4g m to R* = r), "
                "LIGGGHTS' a still 720-facet STL mesh with surface velocity.\n",
                when, std::thread::hardware_concurrency(), 2 * c.drum_radius, c.rpm, c.omega(), c.gravity, c.tilt_deg,
                c.diameter, c.density, c.youngs_modulus, c.poisson_ratio, c.restitution, c.friction,
                c.rolling_friction, c.wall_friction, c.wall_rolling_friction, c.dt, c.layers, phase, o.settle_steps,
                o.liggghts_skin_d, o.stl_facets, o.centrec_skin_d, o.lammps_skin_d, law.tsuji_alpha, law.pair.tsuji,
                c.restitution, law.pair.xgammat, law.pair.k_roll, law.wall.k_roll, law.pair.overlap / c.diameter,
                law.wall.overlap / c.diameter, law.wall.r_eff);
  return b;
}

CentrecRunSettings centrec_settings(const BenchOptions& o, int threads, std::size_t size_index, long particles) {
  CentrecRunSettings cr;
  cr.threads = threads;
  cr.skin_fraction = o.centrec_skin_d;
  cr.settle_steps = o.settle_steps;
  cr.timed_steps = timed_steps_for(o, particles);
  cr.repeats = repeats_of(o, size_index);
  cr.replays = replays_for(o, particles, size_index);
  return cr;
}

// Whether a peer engine's programs were found; says so when not (that engine is skipped).
bool found_or_say(bool found, const char* engine, const std::string& mpirun, const std::string& exe) {
  if (!found) std::printf("warning: %s or %s not found on PATH: %s skipped\n", mpirun.c_str(), exe.c_str(), engine);
  return found;
}

// The protocol of a peer engine's deck (LIGGGHTS, LAMMPS): ranks, skin, settle and timed phases.
template <class Deck>
void set_protocol(Deck& k, const BenchOptions& o, int ranks, std::size_t size_index, long particles, double skin) {
  k.ranks = ranks;
  k.skin = skin;
  k.settle_steps = o.settle_steps;
  k.timed_steps = timed_steps_for(o, particles);
  k.repeats = repeats_of(o, size_index);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const BenchOptions o = parse_bench_options(argc, argv);
    const FilmCase c;
    fs::create_directories(o.out);
    LiggghtsRunSettings lig;
    lig.liggghts = o.liggghts_exe;
    lig.mpirun = o.mpirun;
    LammpsRunSettings lmp;
    lmp.lammps = o.lammps_exe;
    lmp.mpirun = o.mpirun;
    const bool run_lig = o.liggghts && found_or_say(liggghts_available(lig), "LIGGGHTS", o.mpirun, o.liggghts_exe);
    const bool run_lmp = o.lammps && found_or_say(lammps_available(lmp), "LAMMPS", o.mpirun, o.lammps_exe);

    std::vector<BenchRow> rows;
    std::vector<FilmState> states;  // kept for the interleaved centrec phases
    auto write_tables = [&] {
      write_text(o.out + "/results.md", format_markdown(c, rows, preamble(c, o)));
      write_csv(o.out + "/results.csv", rows);
    };
    for (std::size_t si = 0; si < o.sizes.size(); ++si) {
      // One lattice file per N; every engine reads this file (centrec via read_film_state,
      // LIGGGHTS and LAMMPS via the data file converted from what was read back).
      const FilmState made = make_film_lattice(c, o.sizes[si]);
      const std::string dir = o.out + "/N" + std::to_string(made.particles.size());
      fs::create_directories(dir);
      const std::string state_file = dir + "/film_initial_state.txt";
      write_film_state(state_file, made);
      const FilmState& s = states.emplace_back(read_film_state(state_file));
      std::printf("N = %zu (target %ld): periodic length %.4g m = %.1f d, state %s\n", s.particles.size(),
                  o.sizes[si], s.length, s.length / c.diameter, state_file.c_str());
      const std::string work_dir = fs::absolute(dir).string();
      if (run_lig || run_lmp) write_liggghts_data(work_dir + "/data.film", c, s);
      lmp.work_dir = work_dir;
      lmp.deck.data_file = work_dir + "/data.film";
      if (run_lig) {
        lig.work_dir = work_dir;
        lig.deck.data_file = work_dir + "/data.film";
        lig.deck.stl_file = lig.work_dir + "/drum.stl";
        // Facets about 10 times longer than wide: LIGGGHTS was as fast with these as with
        // full-length ones, and refuses triangles whose smallest angle is below its
        // curvature limit (about 0.26 deg). An even count puts a facet edge on the 2-rank split.
        int axial = centrec::liggghts::facets_along(c.drum_radius, s.length, o.stl_facets);
        axial += axial % 2;
        const long tris = centrec::liggghts::write_cylinder_stl(lig.deck.stl_file, c.drum_radius, s.length, o.stl_facets, axial);
        lig.deck.curvature_deg = centrec::liggghts::cylinder_curvature_deg(c.drum_radius, s.length, o.stl_facets, axial);
        std::printf("  LIGGGHTS mesh: %ld triangles (%d around x %d along z), curvature %.3g deg\n", tris, o.stl_facets,
                    axial, lig.deck.curvature_deg);
      }
      for (int t : o.threads) {
        BenchRow row;
        row.particles = static_cast<long>(s.particles.size());
        row.workers = t;
        if (run_lig) {
          set_protocol(lig.deck, o, t, si, row.particles, o.liggghts_skin_d * c.diameter);
          row.liggghts = run_liggghts(c, s, lig);
          print_result(row.liggghts);
        }
        if (run_lmp) {
          set_protocol(lmp.deck, o, t, si, row.particles, o.lammps_skin_d * c.diameter);
          row.lammps = run_lammps(c, s, lmp);
          print_result(row.lammps);
        }
        if (o.centrec && !o.interleave) {
          row.centrec = run_centrec(c, s, centrec_settings(o, t, si, row.particles));
          print_result(row.centrec);
        }
        rows.push_back(row);
        // Rewrite the tables after every point so an interrupted run keeps what it measured.
        write_tables();
      }
    }
    if (o.centrec && o.interleave) {
      for (std::size_t ti = 0; ti < o.threads.size(); ++ti) {
        std::vector<std::unique_ptr<CentrecFilmRun>> runs;
        // Each size's phases spread evenly over the run: phase k of a size with K phases
        // in all goes at (k + 1/2) / K of the way (a stable order keeps ties by size).
        std::vector<std::pair<double, std::size_t>> schedule;
        for (std::size_t si = 0; si < states.size(); ++si) {
          const CentrecRunSettings cr = centrec_settings(o, o.threads[ti], si, static_cast<long>(states[si].particles.size()));
          runs.push_back(std::make_unique<CentrecFilmRun>(c, states[si], cr));
          const int phases = cr.replays * cr.repeats;
          for (int k = 0; k < phases; ++k) schedule.emplace_back((k + 0.5) / phases, si);
        }
        std::stable_sort(schedule.begin(), schedule.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [when, si] : schedule) runs[si]->time_phase();
        for (std::size_t si = 0; si < states.size(); ++si) {
          BenchRow& row = rows[si * o.threads.size() + ti];
          row.centrec = runs[si]->finish();
          std::printf("N = %ld, phases interleaved with the other sizes':\n", row.particles);
          print_result(row.centrec);
        }
        write_tables();
      }
    }
    const std::string md = format_markdown(c, rows, preamble(c, o));
    std::printf("\n%s\nWritten: %s/results.md, %s/results.csv\n", md.c_str(), o.out.c_str(), o.out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "centrec_bench_film: %s\n", e.what());
    return 1;
  }
}
