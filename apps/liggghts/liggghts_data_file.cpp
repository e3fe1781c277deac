#include "liggghts/liggghts_data_file.hpp"

#include <cstdio>

namespace centrec::liggghts {

std::string liggghts_data_file(const std::string& title, const LiggghtsBox& box, const std::vector<LiggghtsAtom>& atoms) {
  std::string d = title + " (atom_style granular)\n\n" + std::to_string(atoms.size()) + " atoms\n2 atom types\n\n";
  char line[512];
  std::snprintf(line, sizeof line, "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\nAtoms\n\n", box.lo[0],
                box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2]);
  d += line;
  // atom_style granular: id type diameter density x y z
  for (std::size_t k = 0; k < atoms.size(); ++k) {
    const LiggghtsAtom& a = atoms[k];
    std::snprintf(line, sizeof line, "%zu 1 %.17g %.17g %.17g %.17g %.17g\n", k + 1, a.diameter, a.density, a.x.x, a.x.y,
                  a.x.z);
    d += line;
  }
  // Velocities for atom_style granular: id vx vy vz wx wy wz
  d += "\nVelocities\n\n";
  for (std::size_t k = 0; k < atoms.size(); ++k) {
    const LiggghtsAtom& a = atoms[k];
    std::snprintf(line, sizeof line, "%zu %.17g %.17g %.17g %.17g %.17g %.17g\n", k + 1, a.v.x, a.v.y, a.v.z, a.w.x,
                  a.w.y, a.w.z);
    d += line;
  }
  return d;
}

}  // namespace centrec::liggghts
