#pragma once
// A LAMMPS data file for LIGGGHTS' atom_style granular: two atom types (1 = particles,
// 2 = walls; every atom here is a particle), the box, then each atom's diameter, density,
// position and its velocity and spin, at full precision. The one writer behind the
// exported deck's starting state and the benchmark's settled film.
#include <string>
#include <vector>

#include "dem/vec3.hpp"

namespace centrec::liggghts {

struct LiggghtsAtom {
  double diameter = 0.0;  // m
  double density = 0.0;   // kg/m3
  dem::Vec3 x, v, w;      // m, m/s, rad/s
};

struct LiggghtsBox {
  double lo[3], hi[3];  // m
};

// The file's text; `title` is its first line (before " (atom_style granular)"). Atom ids
// are 1.. in the order given.
std::string liggghts_data_file(const std::string& title, const LiggghtsBox& box, const std::vector<LiggghtsAtom>& atoms);

}  // namespace centrec::liggghts
