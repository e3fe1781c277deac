#include "liggghts/liggghts_materials.hpp"

#include <cstdio>

namespace centrec::liggghts {

std::string liggghts_material_commands(const LiggghtsMaterials& m) {
  const LiggghtsContactPair& pp = m.particle_particle;
  const LiggghtsContactPair& pw = m.particle_wall;
  char buf[1600];
  // Matrices are row-major over types (1 particle, 2 wall); wall-wall never meets.
  std::snprintf(buf, sizeof buf,
                "fix m1 all property/global youngsModulus peratomtype %.9g %.9g\n"
                "fix m2 all property/global poissonsRatio peratomtype %.9g %.9g\n"
                "fix m3 all property/global coefficientRestitution peratomtypepair 2 %.9g %.9g %.9g %.9g\n"
                "fix m4 all property/global coefficientFriction peratomtypepair 2 %.9g %.9g %.9g %.9g\n"
                "fix m5 all property/global coefficientRollingFriction peratomtypepair 2 %.9g %.9g %.9g %.9g\n"
                "pair_style gran %s\n"
                "pair_coeff * *\n",
                m.particle_youngs_modulus, m.wall_youngs_modulus, m.particle_poisson_ratio, m.wall_poisson_ratio,
                pp.restitution, pw.restitution, pw.restitution, pw.restitution, pp.friction, pw.friction, pw.friction,
                pw.friction, pp.rolling_friction, pw.rolling_friction, pw.rolling_friction, pw.rolling_friction,
                liggghts_contact_model(pp).c_str());
  return buf;
}

}  // namespace centrec::liggghts
