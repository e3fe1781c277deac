#include "bench/deck_state_report.hpp"

#include <cstdio>

namespace centrec::bench {

std::string state_report_definitions(double wall_r) {
  char b[2048];
  std::snprintf(b, sizeof b,
                "variable vabs atom sqrt(vx*vx+vy*vy+vz*vz)\n"
                "variable omz atom (x*vy-y*vx)/(x*x+y*y)\n"
                "variable rad atom sqrt(x*x+y*y)\n"
                "variable onwall atom v_rad>%.17g\n"
                "variable vzat atom vz\n"
                "compute rke all erotate/sphere\n"
                "compute cn all contact/atom\n"
                "compute cnsum all reduce sum c_cn\n"
                "compute vabs all reduce ave v_vabs\n"
                "compute omz all reduce ave v_omz\n"
                "compute rmin all reduce min v_rad\n"
                "compute rmax all reduce max v_rad\n"
                "compute nwall all reduce sum v_onwall\n"
                "compute vz all reduce ave v_vzat\n"
                "variable s_atoms equal atoms\n"
                "variable s_ke equal ke\n"
                "variable s_rke equal c_rke\n"
                "variable s_vabs equal c_vabs\n"
                "variable s_omz equal c_omz\n"
                "variable s_rmin equal c_rmin\n"
                "variable s_rmax equal c_rmax\n"
                "variable s_vz equal c_vz\n"
                "variable s_pairs equal c_cnsum/2\n"
                "variable s_wall equal c_nwall\n",
                wall_r);
  return b;
}

const char* state_thermo_columns() { return "step atoms ke c_rke c_vabs c_omz c_rmin c_rmax c_vz c_cnsum c_nwall"; }

std::string state_print_command(const char* tag) {
  return std::string("print \"BENCH_STATE ") + tag +
         " atoms ${s_atoms} ke ${s_ke} rke ${s_rke} mean_speed ${s_vabs} mean_omega_z ${s_omz} min_r ${s_rmin} "
         "max_r ${s_rmax} mean_vz ${s_vz} pair_contacts ${s_pairs} wall_contacts ${s_wall}\"\n";
}

}  // namespace centrec::bench
