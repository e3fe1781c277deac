#pragma once
// The small fed drum of the resume tests (tests/scene/test_dem_resume.cpp,
// tests/reliability/test_interrupt_resume.cpp).

namespace centrec::testing {

// A small fed drum (feeder RNG, outlet, rough wall, sampler all in the state): D/d = 25,
// 12.5 d long, 0.04 s of spin-up and 2 sampled turns of 4 snapshots.
inline const char* const kResumeCase = R"(title: resume
dem:
  drum: {diameter: 0.03, length: 0.015, tilt_deg: 45, speed_rpm: 320.16}
  rough_wall: {enabled: true}
  feeder: {mass_flow: 4.0e-3, axial_length_d: 3}
  initial_film: {particles: 500}
  run: {duration: 0.04, dt: 2.0e-5, skin_d: 0.4, threads: 1, checkpoint_interval: 1.0e-9, progress_interval: 1000}
  sampling: {turns: 2, snapshots_per_turn: 4, axial_sections: 4, tangential_bins: 12, bins: 6}
)";

}  // namespace centrec::testing
