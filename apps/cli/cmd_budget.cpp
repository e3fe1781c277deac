#include <cmath>
#include <cstdio>
#include <fstream>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "config/case_file.hpp"
#include "io/atomic_write.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "io/summary_json.hpp"
#include "runs/thermal_budget.hpp"

namespace centrec::cli {

int cmd_budget(const Args& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: centrec budget CASE.yaml --out DIR [--film FILM.h5] [--samples N] [--seed S] [--overwrite]\n"
        "                      [--replicas-from RUN_DIR/summary.json]\n\n"
        "The error budget of the case's outlet temperature, receiver efficiency and k_eff\n"
        "(docs/error_budget.md): each uncertain input of the thermal model (the particle's c_p,\n"
        "k_s, absorptance and emissivity with the ranges of docs/particle_data.md; the cavity's\n"
        "convection; the Beer-Lambert depth; the film's mixing; the film-top radiation model,\n"
        "surface or two_flux, the case's thermal.radiation.film_top its nominal; the aperture\n"
        "power) is set to both ends of its stated range with the others nominal (one at a time),\n"
        "then all are drawn together in a Latin hypercube of N samples (default 40, seed 12345:\n"
        "the same samples on every run). Every sample is a steady thermal solve of the case's film; no\n"
        "DEM is run. A coupled case (its film from the DEM) needs --film, the film.h5 a\n"
        "`centrec run` of it wrote. --replicas-from takes the DEM's spread over seeds from the\n"
        "summary.json of `centrec run --replicas N` and adds it in quadrature.\n\n"
        "Prints the table (change of each output at the two ends, each input's share of the\n"
        "variance of T_out one at a time and from a linear fit to the hypercube) and writes\n"
        "DIR/summary.json (every sample, the inputs' ranges, bases and sources).\n");
    return 0;
  }
  if (args.empty()) throw UsageError("no case file given (centrec budget --help)");
  std::string case_path, out_dir, film_path;
  runs::BudgetSettings s;
  long samples = s.lhs_samples;
  long seed = static_cast<long>(s.seed);
  CommandLine app("budget");
  app.add_option("CASE", case_path)->required();
  app.add_option("--out", out_dir)->required();
  app.add_option("--film", film_path);
  std::string replicas_path;
  app.add_option("--replicas-from", replicas_path);
  app.add_option("--samples", samples)->check(integer_in(12, 100000));
  app.add_option("--seed", seed)->check(integer_in(0, 2147483647));
  bool overwrite = false;
  add_overwrite_flag(app, overwrite);
  app.read(args);
  s.lhs_samples = static_cast<int>(samples);
  s.seed = static_cast<std::uint64_t>(seed);
  const config::CaseFile cf = config::read_case_file(case_path);
  if (!cf.thermal) throw UsageError(case_path + " has no thermal section: nothing to budget");
  config::ThermalCase c = *cf.thermal;
  if (!film_path.empty()) {
    c.film = io::read_film_field(io::H5File::open_read(film_path), "/film");
    if (c.film.particle_diameter > 0.0 && std::abs(c.film.particle_diameter / c.model.material.d - 1.0) > 1e-6)
      throw UsageError(film_path + ": the film is for particles of d = " + std::to_string(c.film.particle_diameter) +
                       " m but the case's are " + std::to_string(c.model.material.d) + " m");
    c.film_source = {config::FilmSource::Kind::file, film_path, ""};
  } else if (c.film_source.from_dem()) {
    throw UsageError(case_path + " takes its film from the DEM: give --film OUT/film.h5 from a `centrec run` of it "
                                 "(the budget runs no DEM)");
  }
  runs::ReplicaSpread dem;
  if (!replicas_path.empty()) {
    std::ifstream in(replicas_path);
    if (!in) throw UsageError("--replicas-from " + replicas_path + ": cannot be read");
    try {
      dem = runs::replica_spread_from_summary(nlohmann::json::parse(in), replicas_path);
    } catch (const std::exception& e) {
      throw UsageError(std::string("--replicas-from: ") + e.what());
    }
  }
  const io::OutputFolder out(out_dir);
  const io::RunFolderClaim claim(out_dir, "centrec budget " + case_path, folder_use(overwrite));
  runs::BudgetResult r = runs::run_thermal_budget(c, s);
  if (dem.given) runs::add_replica_spread(r, dem);
  nlohmann::json j = runs::budget_json(r);
  j["film"] = c.film_source.text();
  io::write_json_file(out_dir + "/summary.json", j);
  runs::print_budget_table(r);
  std::printf("wrote %s/summary.json\n", out_dir.c_str());
  return 0;
}

}  // namespace centrec::cli
