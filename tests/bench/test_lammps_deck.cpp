// The LAMMPS peer of the film benchmark (apps/bench/lammps_deck.cpp): the deck carries
// centrec's / LIGGGHTS' law in LAMMPS' terms (docs/dem_physics.md), the installed LAMMPS
// turns those numbers into the same contact forces, and the film is carried round by the
// rotating drum region without losing a particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/lammps_deck.hpp"
#include "bench/lammps_run.hpp"
#include "bench/liggghts_deck.hpp"
#include "dem/hertz_mindlin.hpp"
#include "dem/material.hpp"
#include "liggghts/liggghts_launch.hpp"

namespace centrec::bench {
namespace {

namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream b;
  b << in.rdbuf();
  return b.str();
}

// The deck line starting with `head`, split at blanks ("" if absent).
std::vector<std::string> line_tokens(const std::string& deck, const std::string& head) {
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, head.size(), head) == 0) {
      std::istringstream l(line);
      std::vector<std::string> t;
      for (std::string w; l >> w;) t.push_back(w);
      return t;
    }
  return {};
}

// The number after `key` in a token list (NaN if absent); `skip` more tokens first.
double after(const std::vector<std::string>& t, const std::string& key, int skip = 0) {
  for (std::size_t i = 0; i + 1 + skip < t.size(); ++i)
    if (t[i] == key) return std::stod(t[i + 1 + skip]);
  return std::nan("");
}

fs::path scratch(const char* name) {
  const fs::path dir = fs::temp_directory_path() / ("centrec_test_lammps_" + std::string(name));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

bool lammps_here() { return lammps_available(LammpsRunSettings{}); }

// The polynomial LAMMPS' pair style granular applies to the `damping tsuji` parameter.
double tsuji_alpha(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
         18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

TEST(LammpsDeck, DeckCarriesTheLaw) {
  const FilmCase c;
  const FilmState s = make_film_lattice(c, 9000);
  const fs::path dir = scratch("deck");
  LammpsDeckSettings k;
  k.data_file = (dir / "data.film").string();
  k.skin = 0.4 * c.diameter;
  k.settle_steps = 100;
  k.timed_steps = 50;
  k.repeats = 3;
  write_lammps_deck((dir / "in.film").string(), c, s, k);
  const std::string deck = read_text((dir / "in.film").string());

  // The paper's materials, derived here from the formulas of docs/dem_physics.md.
  const double E = 5e6, nu = 0.3, r = 0.6e-3, R = 0.06, d = 1.2e-3;
  const double E_star = E / (2.0 * (1.0 - nu * nu)), G_star = E / (4.0 * (2.0 - nu) * (1.0 + nu));
  const double le = std::log(0.46), beta = le / std::sqrt(le * le + M_PI * M_PI);
  const double wall_r_eff = r * 2.0 * R / (2.0 * R - r);
  const double rel = 1e-12;

  const auto pair = line_tokens(deck, "pair_coeff * * ");
  ASSERT_FALSE(pair.empty()) << deck;
  EXPECT_NEAR(after(pair, "hertz/material"), E, E * rel);
  EXPECT_NEAR(after(pair, "hertz/material", 2), nu, rel);
  // LAMMPS' Tsuji factor equals LIGGGHTS' dashpot sqrt(5) |beta| (not the restitution 0.46).
  EXPECT_NEAR(tsuji_alpha(after(pair, "hertz/material", 1)), std::sqrt(5.0) * std::fabs(beta), 1e-9);
  EXPECT_NE(std::find(pair.begin(), pair.end(), "tsuji"), pair.end());
  EXPECT_NEAR(after(pair, "mindlin"), 8.0 * G_star, 8.0 * G_star * rel);
  EXPECT_NEAR(after(pair, "mindlin", 1), std::sqrt(4.0 * G_star / E_star), rel);
  EXPECT_NEAR(after(pair, "mindlin", 2), 0.81, rel);
  // Rolling: EPSD2's k_t R*^2 at the pair overlap 1.5e-3 d, R* = r / 2; no dashpot.
  const double k_roll = 8.0 * G_star * std::sqrt(0.5 * r * 1.5e-3 * d);
  EXPECT_NEAR(after(pair, "sds"), k_roll, k_roll * rel);
  EXPECT_EQ(after(pair, "sds", 1), 0.0);
  EXPECT_NEAR(after(pair, "sds", 2), 0.26, rel);

  const auto wall = line_tokens(deck, "fix wall all wall/gran/region granular ");
  ASSERT_FALSE(wall.empty()) << deck;
  const double scale = std::sqrt(r / wall_r_eff);
  EXPECT_NEAR(after(wall, "hertz/material"), 2.0 * (1.0 - nu) * E_star * scale, E * rel);
  EXPECT_NEAR(tsuji_alpha(after(wall, "hertz/material", 1)), std::sqrt(5.0) * std::fabs(beta), 1e-9);
  EXPECT_NEAR(after(wall, "mindlin"), 8.0 * G_star * scale, 8.0 * G_star * rel);
  EXPECT_NEAR(after(wall, "mindlin", 2), 10000.0, 10000.0 * rel);
  const double k_roll_wall = 8.0 * G_star * std::sqrt(r * 1.6e-3 * d) * (r / wall_r_eff) * (r / wall_r_eff);
  EXPECT_NEAR(after(wall, "sds"), k_roll_wall, k_roll_wall * rel);
  EXPECT_NEAR(after(wall, "sds", 2), 0.26 * r / wall_r_eff, rel);
  EXPECT_EQ(wall.back(), "drum");

  // The drum turns at 160.08 rpm about +z: theta = omega * t.
  const auto theta = line_tokens(deck, "variable theta equal ");
  ASSERT_EQ(theta.size(), 4u);
  EXPECT_NEAR(std::stod(theta[3]), 160.08 * 2.0 * M_PI / 60.0, 1e-12);
  EXPECT_NE(theta[3].find("*step*dt"), std::string::npos);
  EXPECT_NE(deck.find("region drum cylinder z 0 0 0.059999999999999998 INF INF side in units box rotate v_theta 0 0 0 0 0 1\n"),
            std::string::npos);
  const auto gravity = line_tokens(deck, "fix grav all gravity ");
  EXPECT_NEAR(after(gravity, "gravity"), 9.81, rel);
  EXPECT_NEAR(after(gravity, "vector", 1), -9.81 * std::cos(M_PI / 4) / 9.81, rel);
  EXPECT_NEAR(after(gravity, "vector", 2), 9.81 * std::sin(M_PI / 4) / 9.81, rel);
  for (const char* line : {"newton off\n", "comm_modify vel yes\n", "processors 1 1 *\n", "boundary f f p\n",
                           "neigh_modify delay 0 every 1 check yes\n", "fix integ all nve/sphere\n",
                           "atom_style sphere\n", "timestep 1.0000000000000001e-05\n"})
    EXPECT_NE(deck.find(line), std::string::npos) << line;
  // One initialised run (the settle), then timed runs without set-up.
  EXPECT_NE(deck.find("run 100\n"), std::string::npos);
  std::size_t timed = 0;
  for (std::size_t p = deck.find("run 50 pre no\n"); p != std::string::npos; p = deck.find("run 50 pre no\n", p + 1))
    ++timed;
  EXPECT_EQ(timed, 3u);
  fs::remove_all(dir);
}

// An SDS case (dem/rolling_models.hpp: LAMMPS has `rolling sds`) exports its own k_roll,
// gamma_roll and mu_roll, the wall's scaled from R* = r to LAMMPS' r_eff (torque k r_eff^2
// theta equal to k R*^2 theta); CDT, which LAMMPS lacks, is refused by name.
TEST(LammpsDeck, SdsCaseExportsItsOwnCoefficients) {
  FilmCase c;
  c.rolling_model = centrec::dem::RollingModel::sds;
  c.rolling_coefficients = {250.0, 0.02};
  const std::string deck = lammps_contact_commands(c, lammps_law(c));
  const auto pair = line_tokens(deck, "pair_coeff * * ");
  EXPECT_EQ(after(pair, "sds"), 250.0);
  EXPECT_EQ(after(pair, "sds", 1), 0.02);
  EXPECT_EQ(after(pair, "sds", 2), 0.26);
  const double r = 0.6e-3, R = 0.06, wall_r_eff = r * 2.0 * R / (2.0 * R - r), s2 = (r / wall_r_eff) * (r / wall_r_eff);
  const auto wall = line_tokens(deck, "fix wall all wall/gran/region granular ");
  EXPECT_NEAR(after(wall, "sds"), 250.0 * s2, 1e-12 * 250.0);
  EXPECT_NEAR(after(wall, "sds", 1), 0.02 * s2, 1e-15);
  EXPECT_NEAR(after(wall, "sds", 2), 0.26 * r / wall_r_eff, 1e-12);
  c.rolling_model = centrec::dem::RollingModel::cdt;
  try {
    lammps_law(c);
    FAIL() << "a CDT case was given an SDS rolling model";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rolling_model: cdt"), std::string::npos) << e.what();
  }
}

// Two particles and one at the wall, overlapping and moving: the deck's coefficients give
// centrec's Hertz-Mindlin normal force and both dashpots (dem/hertz_mindlin.hpp), for the
// pair and for the drum wall, at the set-up and after a step of a run continued without
// set-up (the deck's timed runs), where the wall also moves at omega R. The step is 1e-12 s,
// so nothing else changes measurably.
TEST(LammpsDeck, ContactLawMatchesCentrec) {
  if (!lammps_here()) GTEST_SKIP() << "mpirun or lmp not on PATH";
  const FilmCase c;
  const double r = c.radius(), m = c.density * M_PI / 6.0 * std::pow(c.diameter, 3);
  const double delta = 1.5e-3 * c.diameter, delta_w = 1.6e-3 * c.diameter, vn = 0.01, vt = 0.02;
  const fs::path dir = scratch("probe");
  std::string deck =
      "units si\natom_style sphere\natom_modify map array\nboundary f f p\nnewton off\ncomm_modify vel yes\n"
      "region box block -0.0606 0.0606 -0.0606 0.0606 0 0.01 units box\ncreate_box 1 box\n";
  char b[512];
  std::snprintf(b, sizeof b,
                "create_atoms 1 single 0 0 0.005 units box\n"
                "create_atoms 1 single %.17g 0 0.005 units box\n"
                "create_atoms 1 single %.17g 0 0.002 units box\n"
                "set type 1 diameter %.17g\nset type 1 density %.17g\n",
                c.diameter - delta, c.drum_radius - r + delta_w, c.diameter, c.density);
  deck += b;
  deck += lammps_contact_commands(c, lammps_law(c));
  std::snprintf(b, sizeof b,
                "timestep 1e-12\nfix integ all nve/sphere\n"
                "set atom 2 vx %.17g vy %.17g\nset atom 3 vx %.17g vy %.17g\n",
                -vn, vt, vn, vt);
  deck += b;
  const char* report = "print \"PROBE $(fx[1]:%.17g) $(fy[1]:%.17g) $(fx[3]:%.17g) $(fy[3]:%.17g)\"\n";
  deck += "thermo_style custom step atoms\nrun 0\n" + std::string(report) + "run 1 pre no\n" + report;
  std::ofstream((dir / "in.probe").string()) << deck;
  const std::string cmd = "cd '" + dir.string() + "' && lmp -in in.probe -log log.probe -screen none > /dev/null 2>&1";
  ASSERT_EQ(liggghts::run_shell(cmd), 0) << read_text((dir / "log.probe").string());

  std::vector<std::vector<double>> probes;
  std::istringstream log(read_text((dir / "log.probe").string()));
  for (std::string line; std::getline(log, line);)
    if (line.rfind("PROBE ", 0) == 0) {
      std::istringstream l(line.substr(6));
      std::vector<double> f(4);
      l >> f[0] >> f[1] >> f[2] >> f[3];
      probes.push_back(f);
    }
  ASSERT_EQ(probes.size(), 2u);

  const dem::Material mat{c.youngs_modulus, c.poisson_ratio, c.density};
  const auto pp = dem::make_pair_constants(mat, mat, {c.restitution, c.friction, c.rolling_friction});
  const auto pw = dem::make_pair_constants(mat, mat, {c.restitution, c.wall_friction, c.wall_rolling_friction});
  const auto kp = dem::hertz_mindlin_coefficients(pp, delta, 0.5 * r, 0.5 * m);
  const auto kw = dem::hertz_mindlin_coefficients(pw, delta_w, r, m);
  // Atom 1 is pushed along -x by atom 2 approaching at vn, and dragged along +y by its
  // sliding at vt; atom 3 presses outwards at vn against the wall and slides along +y,
  // relative to a wall at rest in the set-up and moving at omega R after the step.
  const double f1x = -(kp.kn * delta + kp.gamma_n * vn), f1y = kp.gamma_t * vt;
  const double f3x = -(kw.kn * delta_w + kw.gamma_n * vn);
  const double f3y[2] = {-kw.gamma_t * vt, -kw.gamma_t * (vt - c.omega() * c.drum_radius)};
  for (int k = 0; k < 2; ++k) {
    const auto& f = probes[k];
    EXPECT_NEAR(f[0], f1x, 1e-6 * std::fabs(f1x)) << "probe " << k;
    EXPECT_NEAR(f[1], f1y, 1e-6 * std::fabs(f1y)) << "probe " << k;
    EXPECT_NEAR(f[2], f3x, 1e-6 * std::fabs(f3x)) << "probe " << k;
    EXPECT_NEAR(f[3], f3y[k], 1e-6 * std::fabs(f3y[k])) << "probe " << k;
  }
  fs::remove_all(dir);
}

// A one-layer film of the paper's drum (about 1900 particles), settled 200 steps and
// timed 2 x 50: the rotating region carries it round (a still wall with mu = 10000 would
// brake the wall layer), every particle stays in, and the log gives the benchmark its
// two phases.
TEST(LammpsDeck, FilmIsCarriedRound) {
  if (!lammps_here()) GTEST_SKIP() << "mpirun or lmp not on PATH";
  FilmCase c;
  c.layers = 1;
  const FilmState s = make_film_lattice(c, 1);
  const fs::path dir = scratch("film");
  LammpsRunSettings r;
  r.work_dir = dir.string();
  r.deck.data_file = (dir / "data.film").string();
  r.deck.skin = 0.4 * c.diameter;
  r.deck.settle_steps = 200;
  r.deck.timed_steps = 50;
  r.deck.repeats = 2;
  write_liggghts_data(r.deck.data_file, c, s);
  const EngineResult res = run_lammps(c, s, r);
  ASSERT_TRUE(res.ok) << res.note;
  std::printf("LAMMPS one-layer film, %ld particles: mean omega_z %.4f rad/s settled, %.4f final (drum %.4f); "
              "wall/particle %.3f; phases %.4f / %.4f s; rebuilds/phase %.1f\n",
              res.particles, res.settled.mean_omega_z, res.final.mean_omega_z, c.omega(),
              res.final.wall_contacts / res.particles, res.seconds[0], res.seconds[1], res.rebuilds_per_phase);
  EXPECT_EQ(res.final.atoms, static_cast<long>(s.particles.size()));
  EXPECT_NEAR(res.final.mean_omega_z, c.omega(), 0.1 * c.omega());
  EXPECT_GT(res.final.wall_contacts, 0.5 * res.particles);  // the layer lies on the wall
  EXPECT_LT(res.final.max_radius, c.drum_radius);
  ASSERT_EQ(res.seconds.size(), 2u);
  EXPECT_GT(res.seconds[0], 0.0);
  EXPECT_GT(res.rebuilds_per_phase, 0.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace centrec::bench
