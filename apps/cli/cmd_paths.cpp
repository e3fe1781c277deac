#include <cstdio>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/run_folder.hpp"
#include "io/summary_json.hpp"
#include "runs/particle_paths_run.hpp"

namespace centrec::cli {

int cmd_paths(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec paths CASE.yaml --dem DEM_DIR --results RUN_DIR/results.h5 --out DIR [--overwrite]\n\n"
        "A fed drum's residence-time distribution and its particles heated along their own\n"
        "paths (docs/particle_paths.md). DEM_DIR is a `centrec dem` run of the drum (its\n"
        "tracks/, written during the sampled turns); results.h5 a `centrec run` of CASE on that\n"
        "drum's film (`--dem-from DEM_DIR`), whose thermal solution heats the paths. Prints the\n"
        "residence times (against holdup / feed and the continuum film's), the particles'\n"
        "outlet temperatures (mean against the mixing cup, spread, 5 / 95 %% quantiles) and\n"
        "their peak temperature; writes DIR/summary.json and DIR/paths.csv.\n");
    return 0;
  }
  std::string case_path, dem_dir, results, out_dir;
  CommandLine app("paths");
  app.add_option("CASE", case_path)->required();
  app.add_option("--dem", dem_dir)->required();
  app.add_option("--results", results)->required();
  app.add_option("--out", out_dir)->required();
  bool overwrite = false;
  add_overwrite_flag(app, overwrite);
  app.read(args);
  const config::CaseFile cf = config::read_case_file(case_path);
  if (!cf.thermal) throw UsageError(case_path + " has no thermal section: its T_in and particle heat the paths");
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec paths " + case_path, folder_use(overwrite));
  nlohmann::json j = runs::particle_paths_report(dem_dir, results, *cf.thermal, out_dir);
  io::write_json_file(out_dir + "/summary.json", j);
  std::printf("wrote %s/summary.json and %s/paths.csv\n", out_dir.c_str(), out_dir.c_str());
  return 0;
}

}  // namespace centrec::cli
