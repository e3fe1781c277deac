#pragma once
// The checks a run makes before it starts, in one place (docs/reliability.md): the case
// reader calls them on the DEM a case describes, so `centrec validate` refuses what
// `centrec dem` and `centrec run` refuse, and the commands call them again on the DEM they
// will actually run (receiver derivation and command-line values applied).
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "config/case_dem.hpp"
#include "config/case_receiver.hpp"
#include "config/case_sweep.hpp"
#include "config/case_thermal.hpp"
#include "dem/timestep_advisor.hpp"

namespace centrec::config {

// Command-line values that replace the case's (`centrec dem`, `run`, `sweep`, `thermal`,
// `export-liggghts`; their flags: apps/cli/case_overrides.cpp); unset = the case's.
// Case keys (--threads, --seed, --set KEY=VALUE, ...) are written into the case's resolved
// configuration and read again (with_overrides, config/case_file.hpp), so the key's own
// reader checks them and the outputs record them. The operating point depends on the case
// (the receiver's, or the DEM drum's without one): effective_dem applies it.
struct Overrides {
  std::map<std::string, std::string> keys;  // dotted key path -> the value as YAML scalar text
  std::optional<double> speed_rpm;  // the receiver's speed, or the DEM drum's without a receiver
  std::optional<double> mass_flow;  // the receiver's mass flow, or the DEM feeder's, kg/s
  bool any_operating_point() const { return speed_rpm || mass_flow; }
  bool sets(const std::string& key) const { return keys.count(key) > 0; }
  // Any value that changes or runs the DEM (a case without a DEM takes none).
  bool any_dem() const;
};

// The receiver with the overrides' operating point.
ReceiverCase effective_receiver(const ReceiverCase& r, const Overrides& o);

// The DEM a run simulates: `dem` as given (case keys overridden already, with_overrides), the
// drum and feed the receiver derives (eqs 1-3; see apply_receiver), then the operating
// point. Throws std::invalid_argument when the receiver
// and the DEM disagree (tilt, particle diameter).
DemCase effective_dem(const DemCase& dem, const ReceiverCase* receiver, const Overrides& o);

// One line naming the drum a DEM run simulates: diameter, drum or slice length, speed, the
// flow it runs at (feed or slice target) and the time step; `derived` says it came from
// receiver.dem_diameter_d. What `validate` and `export-liggghts` print.
std::string dem_drum_line(const DemCase& dc, bool derived);

// A refused setting: the key path in the case file it concerns and why.
struct CaseProblem {
  std::string key;
  std::string message;
};

// The time-step advice for the particles and walls this DEM can ever hold (the smallest
// particle of its size distribution and the glued wall spheres), without building it.
dem::TimeStepAdvice dem_time_step_advice(const DemCase& dc);
// The time step the run will use: run.dt, or the advice's recommended step.
double dem_time_step(const DemCase& dc);

// Every check a DEM run makes before it starts: drum, feeder and initial film fit, time
// step within the stability bound, a step count that can finish (at most kMaxSteps), a
// turning drum. `derived` says the drum came from receiver.dem_diameter_d (named in the
// message). nullopt = none.
std::optional<CaseProblem> dem_run_problem(const DemCase& dc, bool derived = false);

// The checks of a coupled run (`centrec run`, film from the DEM) beyond the DEM's: the
// same particles on both sides, sampled turns to take the film from, a cavity aperture
// within the drum the film is scaled to (the receiver's, or the DEM drum's without one).
std::optional<CaseProblem> coupled_run_problem(const DemCase& dem, const ThermalCase& thermal,
                                               const ReceiverCase* receiver);

// The checks of `centrec sweep`: every point of the grid is a `centrec run` with that
// speed and mass flow (Overrides), so each must pass dem_run_problem. The key names the
// swept list (sweep.speed_rpm, sweep.mass_flow) the refused value is in.
std::optional<CaseProblem> sweep_problem(const DemCase& dem, const ReceiverCase* receiver, const SweepSpec& sweep);

// A run of more time steps than this cannot finish (1e10 steps of even one particle are
// days of wall time): a typo in run.dt or run.duration, refused before the run.
constexpr double kMaxSteps = 1e10;

// One sentence on the time step a run uses (run.dt = dt_given, or 0 for the advice's
// recommended step) and the bound it satisfies (the run's first lines).
std::string time_step_statement(const dem::TimeStepAdvice& advice, double dt_given);

}  // namespace centrec::config
