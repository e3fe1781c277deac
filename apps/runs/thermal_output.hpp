#pragma once
// Outputs of `centrec thermal` (docs/outputs.md and docs/thermal_model.md): DIR/thermal.h5 (fields with units
// attributes, the resolved configuration and the code version as root attributes) and the
// headline figures as JSON for DIR/summary.json.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config/case_thermal.hpp"
#include "io/h5_file.hpp"
#include "io/provenance.hpp"
#include "runs/thermal_case_run.hpp"

namespace centrec::runs {

// DIR/thermal.h5 and its XDMF sidecar DIR/thermal.xmf (the temperature field on its grid).
void write_thermal_h5(const std::string& path, const config::ThermalCase& c, const ThermalRun& r);
// The same content into an open file (provenance, /grid, /steady, /transient, /film).
void write_thermal_groups(io::H5File& f, const config::ThermalCase& c, const ThermalRun& r, const io::Provenance& p);
// DIR/along_z.csv: one row per thermal grid column from the feed end to the outlet: z,
// thickness, the mixing-cup temperature leaving it, the surface temperature, the absorbed,
// emitted, convected and wall fluxes and k_eff with its parts (docs/outputs.md).
std::string along_z_csv(const ThermalRun& r);
// What a user of this thermal solution must know (summary.json "warnings", and stdout): a
// film hotter than its particle's data hold.
std::vector<std::string> thermal_warnings(const config::ThermalCase& c, const ThermalRun& r);
// DIR/film_profiles.csv: the film the thermal model solved on, one row per section and wall
// distance (z, eta in m; inside_film 1 up to the section's thickness; u m/s, phi, D m2/s).
std::string film_profiles_csv(const thermal::FilmField& film);
// The XDMF 3 of the film grid in the file named h5_name (beside it): the cell centres as
// points (z, eta, 0), quadrilaterals between them, the steady fields as point data.
std::string thermal_xdmf(const std::string& h5_name, const ThermalRun& r);
// Film-average of a per-section k_eff quantity over the irradiated length (equal sections):
// the `k_eff.film_mean` figures of summary.json.
double section_mean(const std::vector<thermal::KeffSection>& k, double thermal::KeffSection::*m);

// The outlet temperature over a run's transient (has_transient): its end time, s, and T_out at
// the start, the end, its lowest and highest, K.
struct TransientOutlet {
  double t_end, T_start, T_end, T_min, T_max;
};
TransientOutlet transient_outlet(const ThermalRun& r);
nlohmann::json thermal_summary(const config::ThermalCase& c, const ThermalRun& r);
// Three printed lines: the mean solar flux on the film and through the aperture; the
// receiver's power flow (aperture power, carried, losses through the aperture, convective
// and wall losses, receiver efficiency, balance residual).
void print_receiver_report(const config::ThermalCase& c, const ThermalRun& r);
// "0.8977", or why there is none (no sunlight to speak of: thermal::FilmBalance::efficiency).
std::string efficiency_text(double efficiency);

}  // namespace centrec::runs
