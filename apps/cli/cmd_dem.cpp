// `centrec dem CASE.yaml --out DIR`: a DEM-only run of the CentRec scene.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "cli/case_overrides.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/dem_engine_options.hpp"
#include "cli/plot_scripts.hpp"
#include "config/case_checks.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/code_version.hpp"
#include "liggghts/dem_liggghts_run.hpp"
#include "runs/dem_case_run.hpp"
#include "runs/dem_run_report.hpp"
#include "runs/interrupt.hpp"

namespace centrec::cli {

namespace {

struct DemOptions {
  std::string case_path, out_dir = "out/dem", resume_dir;
  bool overwrite = false, out_given = false;
  FigureOptions figures;
  config::Overrides overrides;  // --threads, --duration, --wall-rolling-model, --set
  DemEngineOptions engine;
};

void print_dem_help(const CommandLine& app) {
  std::printf("usage: centrec dem CASE.yaml [options]\n       centrec dem --resume DIR [--threads N] [--set dem.run.max_extension=S] [--set dem.sampling.turns=N]\n\n%s\n",
              app.options_text().c_str());
  std::printf(
      "Runs the DEM of the CentRec drum (or periodic slice) described by the case's\n"
      "`dem:` section (the drum `receiver:` derives when it gives dem_diameter_d, as `centrec\n"
      "run` does) and writes DIR/summary.json (headline figures and the resolved\n"
      "configuration), DIR/dem.h5 (mass flows, averaged film fields, particle snapshots;\n"
      "units as attributes), DIR/dem.xmf and DIR/drum.xmf (open in ParaView), DIR/mass_flow.csv\n"
      "and the paper's figures (apps/plot_dem.py): fig2_mass_flow.png (outlet flow vs time),\n"
      "fig3_film_thickness.png (thickness along z), fig6_velocity_profiles.png (the nine\n"
      "profiles) and solid_fraction.png (--no-plots: none; --figures png,pdf,svg and --dpi N:\n"
      "other formats and resolutions).\n"
      "--threads, --duration, --wall-rolling-model and --set enter the resolved configuration in the\n"
      "outputs and the checkpoint.\n"
      "--engine liggghts runs the same case on LIGGGHTS 3.8 (`mpirun -np N liggghts`, N = --ranks;\n"
      "--mpirun srun for a cluster launcher) in DIR/liggghts and reads its dumps into the same\n"
      "samplers and outputs; settings LIGGGHTS cannot express are refused (see export-liggghts).\n\n"
      "Every run.checkpoint_interval seconds of wall time (default 300; 0 = off) and at the\n"
      "end the run writes DIR/checkpoint.h5 (atomically); Ctrl-C or SIGTERM writes one at the\n"
      "next safe point (the end of a spin-up chunk or of a sampled turn) and stops (a second\n"
      "Ctrl-C stops at once). --resume DIR continues a stopped or killed run from it with the\n"
      "case stored there, --duration included (a CASE.yaml given too must match it); the\n"
      "result is bitwise the same as the uninterrupted run's. A killed sampling turn is\n"
      "sampled again from its start. A run still spinning up (its checkpoint says so) may be\n"
      "resumed with more --set dem.run.max_extension=S (a drum not steady at its cap keeps\n"
      "filling instead of sampling a filling film) or another --set dem.sampling.turns=N; it\n"
      "then equals a whole run started with those values.\n");
}

// Declares the options of `centrec dem` on `app`, each bound to its member of `o`.
void declare(CommandLine& app, DemOptions& o) {
  app.add_option("CASE", o.case_path);
  app.add_option("--out", o.out_dir, "the run's folder (default out/dem)")->option_text("DIR");
  app.add_option("--resume", o.resume_dir, "continue the stopped or killed run in DIR from its checkpoint")
      ->option_text("DIR");
  add_override_flags(app, o.overrides, "dem");
  add_figure_flags(app, o.figures);
  add_overwrite_flag(app, o.overwrite);
  add_engine_options(app, o.engine);
}

// The keys a resumed run still spinning up may change: a drum that is not steady at its
// extension's cap would otherwise sample a filling film or start again from t = 0.
bool lengthens_spin_up(const std::string& key) {
  return key == "dem.run.max_extension" || key == "dem.sampling.turns";
}

// Refuses a lengthening the checkpoint cannot take: the run must still be spinning up, and
// the new cap must lie past its time (the resumed run then equals a whole run started with
// the new values, as the spin-up's chunks up to the checkpoint are the same).
void check_spin_up_lengthening(const DemOptions& o, const io::RunCheckpoint& ck, const config::DemCase& dc) {
  bool lengthened = false;
  for (const auto& [key, value] : o.overrides.keys) lengthened = lengthened || lengthens_spin_up(key);
  if (!lengthened) return;
  if (ck.phase != "spin-up")
    throw UsageError("dem.run.max_extension and dem.sampling.turns change a resumed run only while it spins up; " +
                     io::checkpoint_path(o.resume_dir) + " is in its " + ck.phase + " phase");
  const double t = ck.scene.engine.time, cap = dc.run.duration + dc.run.extension_cap();
  if (cap <= t)
    throw UsageError("dem.run.max_extension: the spin-up would end at t = " + std::to_string(cap) +
                     " s, before the checkpoint's t = " + std::to_string(t) + " s; give a longer one");
}

// Checks what `declare` read; throws UsageError.
void check(DemOptions& o) {
  if (!o.resume_dir.empty()) {
    if (o.engine.engine != "centrec") throw UsageError("--resume is for the native engine (centrec) only");
    // A resumed run continues the case it started with; only the thread count may change,
    // and, while it is still spinning up, how long it may wait for steady flow and how many
    // turns it then samples (checked against the checkpoint in spin_up_lengthening).
    for (const auto& [key, value] : o.overrides.keys)
      if (key != "dem.run.threads" && !lengthens_spin_up(key))
        throw UsageError(key + " cannot change a resumed run: it continues to the " + key.substr(key.find('.') + 1) +
                         " stored in " + io::checkpoint_path(o.resume_dir) +
                         " (the first run's --duration or --set, if it had one; a run still spinning up may be "
                         "given more dem.run.max_extension or dem.sampling.turns)");
    if (o.out_given && std::filesystem::path(o.out_dir).lexically_normal() !=
                           std::filesystem::path(o.resume_dir).lexically_normal())
      throw UsageError("--resume " + o.resume_dir + " continues the run in that folder; --out " + o.out_dir +
                       " would be another: give --resume alone (a copy of the folder resumes where it lies)");
    if (o.overwrite) throw UsageError("--overwrite starts a new run; --resume continues one: give one of them");
    o.out_dir = o.resume_dir;
  }
  if (o.case_path.empty() && o.resume_dir.empty()) throw UsageError("no case file given (centrec dem --help)");
}

}  // namespace

int cmd_dem(const Args& args) {
  DemOptions o;
  CommandLine app("dem");
  declare(app, o);
  if (wants_help(args)) {
    print_dem_help(app);
    return 0;
  }
  app.read(args);
  o.out_given = app.count("--out") > 0;
  // `dem` runs the case's dem: section (with the drum receiver: derives): any other key
  // would change nothing it does.
  for (const auto& [key, value] : o.overrides.keys)
    if (key.rfind("dem.", 0) != 0 && key.rfind("receiver.", 0) != 0)
      throw UsageError("--set " + key + "=" + value + ": `centrec dem` runs the case's dem: section (and the drum "
                       "receiver: derives); " + key + " changes nothing it does (`centrec run` takes it)");
  check(o);
  const DemOptions& opt = o;
  // A resumed run takes its case from the checkpoint (a case file given too must match).
  std::optional<io::RunCheckpoint> ck;
  if (!opt.resume_dir.empty()) ck = io::read_checkpoint(opt.resume_dir);
  config::CaseFile cf = ck ? config::read_case_text(ck->resolved_yaml, ck->case_path) : config::read_case_file(opt.case_path);
  if (!cf.dem) throw std::invalid_argument(cf.path + " has no `dem:` section");
  if (ck && !opt.case_path.empty()) {
    // The stored case holds the first run's values of `dem`'s own flags (--duration, --threads,
    // --wall-rolling-model): compare the case file with those taken from it (a first run with
    // --set resumes without the case file).
    config::Overrides stored;
    for (const std::string& key : override_keys("dem")) stored.keys[key] = config::resolved_value(cf, key);
    if (config::with_overrides(config::read_case_file(opt.case_path), stored).resolved_yaml != cf.resolved_yaml)
      throw std::invalid_argument(opt.case_path + " does not match the case stored in " +
                                  io::checkpoint_path(opt.resume_dir) +
                                  "; resume without the case file, or start a new run");
  }
  if (ck && ck->code_version != centrec::io::code_version())
    std::fprintf(stderr, "centrec dem: warning: checkpoint written by %s, resuming with %s\n", ck->code_version.c_str(),
                 centrec::io::code_version());
  // The command-line values enter the resolved case (outputs and checkpoint record what
  // ran) and pass the same checks as the case file's; effective_dem applies them, as for
  // `centrec run`.
  cf = checked_overrides(cf, opt.overrides, "dem");
  const config::DemCase dc = checked_dem(cf, opt.overrides, "dem");
  if (ck) check_spin_up_lengthening(opt, *ck, dc);
  const io::OutputFolder out(opt.out_dir);
  const io::RunFolderClaim claim(opt.out_dir, "centrec dem " + (ck ? "--resume " + opt.resume_dir : opt.case_path),
                                 ck ? io::FolderUse::resume : folder_use(opt.overwrite));
  try {
    if (opt.engine.engine == "liggghts") {
      liggghts::LiggghtsLaunch launch;
      launch.ranks = opt.engine.ranks;
      launch.mpirun = opt.engine.mpirun;
      launch.liggghts = opt.engine.liggghts;
      runs::run_dem_case(cf, dc, opt.out_dir, liggghts::liggghts_engine(launch));
    } else {
      runs::run_dem_case(cf, dc, opt.out_dir, runs::native_engine(ck));
    }
  } catch (const runs::RunInterrupted& e) {
    std::fprintf(stderr, "centrec dem: %s\n  continue with: centrec dem --resume %s\n", e.what(), opt.out_dir.c_str());
    return 128 + e.signal();
  } catch (const runs::OutputsInterrupted& e) {
    std::fprintf(stderr, "centrec dem: %s; no figures drawn\n", e.what());
    return 128 + e.signal();
  }
  run_plot_script("centrec dem", "plot_dem.py", {opt.out_dir}, opt.figures);
  return 0;
}

}  // namespace centrec::cli
