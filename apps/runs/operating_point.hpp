#pragma once
// The operating point that reaches a target outlet temperature (docs/operating.md): the
// case's thermal model (its flux, inlet temperature, cavity) on the film surrogate of an
// operating map, the mass flow found at each speed of the stable window by bracketed root
// finding (T_out falls with the mass flow), the speed chosen by a stated criterion.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "config/case_thermal.hpp"
#include "coupling/film_surrogate.hpp"
#include "runs/operating_map.hpp"
#include "thermal/outlet_controller.hpp"

namespace centrec::runs {

// The case's thermal model on the surrogate's film at (speed, mass flow), the mass flow
// imposed on the surrogate film by one velocity factor as a coupled run does
// (coupling/film_mass_flow.hpp): the factor says how far the surrogate's own flow is off.
class SurrogateThermal {
 public:
  SurrogateThermal(config::ThermalCase base, const coupling::FilmSurrogate& surrogate, double receiver_diameter);
  struct Answer {
    double T_out = 0.0, efficiency = 0.0, T_surface_max = 0.0;  // K, -, K
    double T_max = 0.0;  // K: the film's hottest cell (particles beneath the radiating surface are hotter)
    double thickness_d = 0.0;                                   // film thickness in particle diameters
    double velocity_factor = 0.0;                               // imposed flow / the surrogate film's own
    double seconds = 0.0;                                       // wall time of the steady solve
  };
  Answer at(double speed_rpm, double mass_flow) const;
  // The thermal case at (speed, mass flow): the surrogate's film, its flow imposed.
  config::ThermalCase case_at(double speed_rpm, double mass_flow) const;
  // The surrogate's film at film_mass_flow carrying mass_flow (a flow off the map's: the
  // film of the nearest mapped flow).
  config::ThermalCase case_at(double speed_rpm, double mass_flow, double film_mass_flow) const;
  // The same thermal model on a given film (a map point's own, to check the surrogate's).
  Answer on_film(thermal::FilmField film, double mass_flow) const;

 private:
  config::ThermalCase on_film_case(thermal::FilmField film, double mass_flow, double* velocity_factor) const;
  config::ThermalCase base_;
  const coupling::FilmSurrogate& surrogate_;
  double receiver_diameter_;
};

struct OperatingCandidate {
  double speed_rpm = 0.0, mass_flow = 0.0;  // rpm, kg/s
  bool found = false;
  std::string why_not;                      // when not found
  SurrogateThermal::Answer answer;
  WindowMargin margin;
  int solves = 0;
};

struct OperatingAnswer {
  double target_T_out = 0.0;
  std::string criterion;
  std::vector<OperatingCandidate> candidates;  // one per speed tried, ascending
  int best = -1;                               // index into candidates, -1: none reaches the target
  std::string why_none;                        // set when the map has no window to search at all
};

// What an answer must have besides reaching the target: a film at least min_thickness_d
// thick, and at least min_margin_rpm to the window's speed edges on both sides (efficiency
// rises with speed towards the film's lock, so the best point otherwise sits on the edge).
struct OperatingCriterion {
  double min_thickness_d = 0.0;
  double min_margin_rpm = 0.0;
};

// Tries n_speeds speeds evenly over the window's speeds (less the speed margin at both
// ends); at each, the mass flow in the window's span at that speed whose T_out is the target
// within 0.02 K. The best is the one of highest efficiency among those the criterion accepts.
OperatingAnswer find_operating_point(const OperatingMap& m, const SurrogateThermal& th, double target_T_out,
                                     int n_speeds, const OperatingCriterion& criterion);

// A full coupled run at a speed and mass flow, as the check of an answer runs it.
struct FullRun {
  double mass_flow = 0.0;  // kg/s
  double T_out = 0.0;      // K
};

// The check of an answer by full coupled runs at its speed: the first at the answer's mass
// flow; while T_out misses the target by more than `tolerance`, a secant step in the mass
// flow, the first through the surrogate's slope dT_out/dmdot at the answer, the next ones
// through the last two full runs, up to `max_runs` runs. A step that would leave the
// window's span at that speed (`span`) stops the refinement, as does a slope that is not
// negative (T_out must fall with the mass flow). Returns the runs made, in order, and says
// in `why_stopped` why it stopped short of the tolerance (empty when the last run is within).
struct CheckRefinement {
  std::vector<FullRun> runs;
  std::string why_stopped;
};
CheckRefinement refine_by_full_runs(double target, double mass_flow, double surrogate_slope,
                                    std::pair<double, double> span, int max_runs, double tolerance,
                                    const std::function<double(double)>& full_T_out);

}  // namespace centrec::runs

namespace centrec::runs {

// A flux history at an operating point (docs/operating.md "A passing cloud"): the steady
// state there, then the same flux series three ways: the mass flow held, the PI controller on
// T_out alone, and the PI with the flux fed forward (thermal/outlet_controller.hpp). The
// controller's gains are tuned once on the film's measured step response.
// The film's response time to a feed change over its mean residence time (holdup / mass flow),
// the default of ControlledTransientSettings::tau_film here: measured on the settled fed D/d 80
// drum of the quickstart's film, its feed stepped down 20 %: its holdup follows a first-order lag
// of 1.28-1.40 s with no measurable dead time, 0.18-0.20 of its 7.17 s residence
// (docs/operating.md "The film's response time, measured"). Eqs 1-3 scale both times alike, so
// the ratio carries to the receivers of the same scaled film.
inline constexpr double kFilmResponseOverResidence = 0.19;

struct CloudResponse {
  thermal::ControlledTransientResult fixed, pi, feedforward;
  thermal::OutletTuning tuning;
  double residence_time = 0.0;  // s, the film's holdup / mass flow at the operating point
  double film_response = 0.0;   // s, the film's first-order lag behind the commanded flow, as used
  double efficiency = 0.0;      // steady, at the operating point (the feedforward's eta)
  double film_enthalpy = 0.0;   // J, the film's enthalpy above the inlet state at the operating point
  bool film_follows = false;    // the film followed the surrogate (film_flows given)
};
// The film follows the surrogate (thermal/outlet_controller.hpp, film_at) within the map's
// mass flows `film_flows` (kg/s, lo < hi; outside them the film of the nearest, its velocity
// scaled); film_flows lo >= hi: the film keeps the operating point's geometry.
CloudResponse cloud_response(const SurrogateThermal& th, double speed_rpm, double mass_flow,
                             const thermal::TimeFactor& flux, thermal::ControlledTransientSettings s,
                             std::pair<double, double> film_flows = {0.0, 0.0});

}  // namespace centrec::runs
