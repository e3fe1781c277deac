// The thermal command's edge: bad input gives clear errors naming key, value and range;
// `centrec thermal` writes thermal.h5 (units, config, version) and summary.json; a film
// field round-trips through HDF5 and a case reading it from `film.file` gives the same
// result as the analytic film it came from.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "config/case_thermal.hpp"
#include "io/code_version.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "runs/thermal_case_run.hpp"
#include "tests/test_case_dir.hpp"
#include "thermal/analytic_film.hpp"

using namespace centrec;
using namespace centrec::config;
using namespace centrec::io;
using namespace centrec::runs;
using centrec::testing::temp_dir;
using centrec::testing::write_case;

namespace {
const char* kCase = R"(title: small
film:
  analytic: {thickness: 6.0e-3, u_surface: 0.26, phi: 0.55, D_shear_coeff: 0.05, drum_diameter: 1.0, length: 1.0}
thermal:
  grid: {nz: 40, nxi: 12}
  T_in: 873.15
  flux: {q_film: 1.0e6}
)";

std::string config_error(const std::string& dir, const std::string& text) {
  try {
    read_thermal_case(write_case(dir, text));
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

// Runs the real `centrec` binary; returns its exit code, stdout+stderr in *output.
int run_centrec(const std::string& args, std::string* output = nullptr) {
  const std::string log = std::filesystem::temp_directory_path() / ("centrec_cli_" + std::to_string(::getpid()) + ".log");
  const int status = std::system((std::string(CENTREC_BINARY) + " " + args + " > " + log + " 2>&1").c_str());
  if (output) {
    std::ifstream in(log);
    output->assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  std::filesystem::remove(log);
  return WEXITSTATUS(status);
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}
}  // namespace

TEST(ThermalCli, BadInputNamesKeyValueAndRange) {
  const std::string dir = temp_dir("bad");
  const std::string unknown = config_error(dir, replace(kCase, "  T_in: 873.15", "  T_in: 873.15\n  T_inlet: 5"));
  const std::string negative = config_error(dir, replace(kCase, "thickness: 6.0e-3", "thickness: -6.0e-3"));
  const std::string thin = config_error(dir, replace(kCase, "thickness: 6.0e-3", "thickness: 1.0e-3"));
  const std::string tol = config_error(dir, std::string(kCase) + "  solver: {rtol: 1.0e-30}\n");
  const std::string choice = config_error(dir, replace(kCase, "  T_in: 873.15", "  T_in: 873.15\n  advection: quick"));
  for (const auto& e : {unknown, negative, thin, tol, choice}) std::printf("error: %s\n", e.c_str());
  EXPECT_NE(unknown.find("thermal.T_inlet"), std::string::npos);
  EXPECT_NE(negative.find("film.analytic.thickness"), std::string::npos);
  EXPECT_NE(negative.find("-0.006"), std::string::npos);
  EXPECT_NE(negative.find("range"), std::string::npos);
  EXPECT_NE(thin.find("particle diameter"), std::string::npos);
  EXPECT_NE(tol.find("thermal.solver.rtol"), std::string::npos);
  EXPECT_NE(tol.find("1e-30"), std::string::npos);
  EXPECT_NE(choice.find("van_leer"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ThermalCli, CommandWritesH5AndSummary) {
  const std::string dir = temp_dir("cmd");
  const std::string path = write_case(dir, kCase);
  std::string out;
  EXPECT_EQ(run_centrec("thermal --help", &out), 0);
  EXPECT_NE(out.find("usage: centrec thermal"), std::string::npos);
  EXPECT_EQ(run_centrec("thermal " + path), 2);  // --out missing: usage
  const std::string bad = dir + "/bad.yaml";
  std::ofstream(bad) << replace(kCase, "thickness: 6.0e-3", "thickness: -6.0e-3");
  EXPECT_EQ(run_centrec("thermal " + bad + " --out " + dir + "/bad_out", &out), 2);
  std::printf("bad case: %s", out.c_str());
  EXPECT_NE(out.find("configuration error"), std::string::npos);
  ASSERT_EQ(run_centrec("thermal " + path + " --out " + dir + "/out", &out), 0) << out;
  std::printf("%s", out.c_str());
  io::H5File f = io::H5File::open_read(dir + "/out/thermal.h5");
  std::vector<std::size_t> dims;
  const auto T = f.read("/steady/T", &dims);
  ASSERT_EQ(dims.size(), 2u);
  EXPECT_EQ(dims[0], 40u);
  EXPECT_EQ(dims[1], 12u);
  EXPECT_EQ(f.string_attribute("/steady/T", "units"), "K");
  EXPECT_EQ(f.string_attribute("/steady/keff/k_eff", "units"), "W/(m K)");
  EXPECT_EQ(f.string_attribute("/", "code_version"), centrec::io::code_version());
  EXPECT_NE(f.string_attribute("/", "resolved_config").find("T_in: 873.15"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/thermal.xmf"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/thermal.h5.tmp"));
  std::ifstream js(dir + "/out/summary.json");
  const std::string text((std::istreambuf_iterator<char>(js)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"T_out_K\"", "\"efficiency\"", "\"balance_residual\"", "\"k_eff\"", "\"jacobian_evaluations\""})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  // The steady tolerance the residual was held to: the default 1e-10, or 4 x the round-off
  // floor where that is larger (thermal/steady_state.hpp).
  const nlohmann::json steady = nlohmann::json::parse(text)["solver"]["steady"];
  ASSERT_TRUE(steady.contains("tolerance_applied") && steady.contains("residual_floor")) << steady.dump();
  const double tol = steady["tolerance_applied"], floor = steady["residual_floor"], res = steady["scaled_residual"];
  std::printf("steady: residual %.3g, tolerance applied %.3g, round-off floor %.3g\n", res, tol, floor);
  EXPECT_GT(floor, 0.0);
  EXPECT_DOUBLE_EQ(tol, std::max(1e-10, 4.0 * floor));
  EXPECT_LE(res, tol);
  // along_z.csv: a row per column from the feed end; the mixing-cup temperature leaving each
  // column (through the face to the next) against the flow-weighted (phi u) means of the
  // columns' cell temperatures, taken midway between the two columns (the outlet: extrapolated
  // from the last two), as the advection's smooth face values are; the last one is T_out.
  std::ifstream csv(dir + "/out/along_z.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("z_m,thickness_m,T_mixing_cup_K,T_surface_K,", 0), 0u) << header;
  EXPECT_NE(header.find("keff_mixing_W_mK"), std::string::npos) << header;
  const auto u = f.read("/grid/u"), phi = f.read("/grid/phi");
  const auto cup = f.read("/steady/T_mixing_cup");
  ASSERT_EQ(cup.size(), 40u);
  std::vector<double> column_mean(40);
  for (std::size_t i = 0; i < 40; ++i) {
    double w = 0.0, wT = 0.0;
    for (std::size_t j = 0; j < 12; ++j) {
      w += phi[i * 12 + j] * u[i * 12 + j];
      wT += phi[i * 12 + j] * u[i * 12 + j] * T[i * 12 + j];
    }
    column_mean[i] = wT / w;
  }
  std::size_t rows = 0;
  double worst = 0.0, previous = 0.0;
  while (std::getline(csv, line)) {
    double z, t, Tm;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &z, &t, &Tm), 3) << line;
    ASSERT_LT(rows, 40u);
    EXPECT_NEAR(Tm, cup[rows], 1e-6 * Tm);  // the CSV is the HDF5 series
    const double face = rows + 1 < 40 ? 0.5 * (column_mean[rows] + column_mean[rows + 1])
                                      : 1.5 * column_mean[rows] - 0.5 * column_mean[rows - 1];
    worst = std::max(worst, std::abs(Tm - face));
    EXPECT_GT(Tm, rows == 0 ? 873.15 : previous) << "row " << rows;  // heated along the flow
    previous = Tm;
    ++rows;
  }
  EXPECT_EQ(rows, 40u);
  std::printf("along_z.csv: %zu rows, mixing cup leaving the last column %.6f K (T_out %.6f K), worst |mixing cup - "
              "the columns' phi u means at the face| %.3f K\n",
              rows, previous, nlohmann::json::parse(text)["T_out_K"].get<double>(), worst);
  EXPECT_NEAR(previous, nlohmann::json::parse(text)["T_out_K"].get<double>(), 1e-6 * previous);
  EXPECT_LT(worst, 0.5);
  // film_profiles.csv: the film solved on, a row per section and wall distance, the same
  // numbers as thermal.h5's /film.
  const auto fz = f.read("/film/z"), feta = f.read("/film/eta"), ft = f.read("/film/t");
  const auto fu = f.read("/film/u"), fphi = f.read("/film/phi"), fD = f.read("/film/D");
  std::ifstream profiles(dir + "/out/film_profiles.csv");
  std::getline(profiles, header);
  EXPECT_EQ(header, "z_m,eta_m,inside_film,u_m_s,phi,D_m2_s");
  std::size_t n = 0;
  for (; std::getline(profiles, line); ++n) {
    double z, eta, u_, p_, D_;
    int inside;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%d,%lf,%lf,%lf", &z, &eta, &inside, &u_, &p_, &D_), 6) << line;
    ASSERT_LT(n, fu.size());
    const std::size_t i = n / feta.size(), j = n % feta.size();
    EXPECT_NEAR(z, fz[i], 1e-9 * std::abs(fz[i]) + 1e-15);
    EXPECT_NEAR(eta, feta[j], 1e-9 * feta[j] + 1e-15);
    EXPECT_EQ(inside, feta[j] <= ft[i] ? 1 : 0);
    EXPECT_NEAR(u_, fu[n], 1e-9 * std::abs(fu[n]) + 1e-15);
    EXPECT_NEAR(p_, fphi[n], 1e-9 * fphi[n] + 1e-15);
    EXPECT_NEAR(D_, fD[n], 1e-9 * std::abs(fD[n]) + 1e-18);
  }
  EXPECT_EQ(n, fu.size());
  std::filesystem::remove_all(dir);
}

TEST(ThermalCli, FilmFieldFileGivesSameResultAsAnalyticFilm) {
  const std::string dir = temp_dir("film");
  const ThermalCase analytic = read_thermal_case(write_case(dir, kCase));
  {
    io::H5File f = io::H5File::create(dir + "/film.h5");
    io::write_film_field(f, analytic.film);
    f.commit();
  }
  const ThermalCase from_file = read_thermal_case(write_case(
      dir, replace(kCase,
                   "  analytic: {thickness: 6.0e-3, u_surface: 0.26, phi: 0.55, D_shear_coeff: 0.05, "
                   "drum_diameter: 1.0, length: 1.0}",
                   "  file: film.h5")));
  EXPECT_EQ(from_file.film.u, analytic.film.u);
  EXPECT_EQ(from_file.film.D, analytic.film.D);
  const double a = run_thermal_case(analytic).balance.T_out, b = run_thermal_case(from_file).balance.T_out;
  std::printf("T_out analytic film %.9f K, same film through HDF5 %.9f K (tolerance 1e-9 K)\n", a, b);
  EXPECT_NEAR(a, b, 1e-9);
  std::filesystem::remove_all(dir);
}

TEST(ThermalCli, CsvFluxTableEqualsUniformFlux) {
  const std::string dir = temp_dir("csv");
  std::ofstream(dir + "/flux.csv") << "z_m,q_W_m2\n# constant table\n0.0, 1.0e6\n0.5, 1.0e6\n1.0, 1.0e6\n";
  const double uniform = run_thermal_case(read_thermal_case(write_case(dir, kCase))).balance.T_out;
  const double table = run_thermal_case(read_thermal_case(write_case(
                                            dir, replace(kCase, "flux: {q_film: 1.0e6}",
                                                         "flux: {profile: table, table_file: flux.csv}"))))
                           .balance.T_out;
  std::printf("T_out uniform %.9f K, constant CSV table %.9f K (tolerance 1e-9 K)\n", uniform, table);
  EXPECT_NEAR(uniform, table, 1e-9);
  std::ofstream(dir + "/bad.csv") << "0.0, 1.0e6\n0.5; 1.0e6\n";
  const std::string e = config_error(dir, replace(kCase, "flux: {q_film: 1.0e6}", "flux: {profile: table, table_file: bad.csv}"));
  std::printf("error: %s\n", e.c_str());
  EXPECT_NE(e.find("bad.csv:2"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// `centrec budget`: its summary.json holds the nominal state (the same T_out as `centrec
// thermal` of the case, 1e-9 K), every input with its range and both ends, and the
// hypercube's samples (as many as asked); a coupled case without --film is refused naming
// --film (the budget runs no DEM).
TEST(ThermalCli, BudgetWritesItsTableAndRefusesADemFilmItDoesNotHave) {
  const std::string dir = temp_dir("budget_cmd");
  const std::string path = write_case(dir, kCase);
  std::string out;
  EXPECT_EQ(run_centrec("budget --help", &out), 0);
  EXPECT_NE(out.find("usage: centrec budget"), std::string::npos);
  ASSERT_EQ(run_centrec("thermal " + path + " --out " + dir + "/thermal", &out), 0) << out;
  ASSERT_EQ(run_centrec("budget " + path + " --out " + dir + "/budget --samples 12 --seed 7", &out), 0) << out;
  std::printf("%s", out.c_str());
  EXPECT_NE(out.find("| c_p |"), std::string::npos);
  std::ifstream ts(dir + "/thermal/summary.json"), bs(dir + "/budget/summary.json");
  const nlohmann::json t = nlohmann::json::parse(ts), b = nlohmann::json::parse(bs);
  std::printf("budget nominal T_out %.10f K, centrec thermal %.10f K\n", b["nominal"]["T_out_K"].get<double>(),
              t["T_out_K"].get<double>());
  EXPECT_NEAR(b["nominal"]["T_out_K"].get<double>(), t["T_out_K"].get<double>(), 1e-9);
  EXPECT_EQ(b["latin_hypercube"]["samples"], 12);
  EXPECT_EQ(b["latin_hypercube"]["seed"], 7);
  EXPECT_EQ(b["latin_hypercube"]["outputs"].size(), 12u);
  ASSERT_EQ(b["inputs"].size(), 11u);  // with the cavity's wind speed and spillage and the film-top model
  for (const auto& in : b["inputs"]) {
    EXPECT_LT(in["lo"].get<double>(), in["hi"].get<double>()) << in.dump();
    EXPECT_TRUE(in["at_lo"].contains("T_out_K") && in["at_hi"].contains("efficiency")) << in.dump();
    EXPECT_FALSE(in["source"].get<std::string>().empty());
  }
  const std::string coupled = dir + "/coupled.yaml";
  std::ifstream src(CENTREC_SOURCE_DIR "/cases/quickstart.yaml");
  std::ofstream(coupled) << src.rdbuf();
  EXPECT_EQ(run_centrec("budget " + coupled + " --out " + dir + "/budget_dem", &out), 2);
  std::printf("coupled without --film: %s", out.c_str());
  EXPECT_NE(out.find("--film"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// A cavity run's per-surface outputs carry the surfaces' axial positions as their dimension
// scale: the rings' centres from the back, then the back plate at z = 0, then the front
// annulus (the shipped cavity case has one) at z = L.
TEST(ThermalCli, CavitySurfacesHaveTheirAxialPositions) {
  const std::string dir = temp_dir("cavity_z");
  ASSERT_EQ(run_centrec("thermal " CENTREC_SOURCE_DIR "/cases/thermal_centrec_cavity.yaml --out " + dir + "/out"), 0);
  const io::H5File f = io::H5File::open_read(dir + "/out/thermal.h5");
  const auto z = f.read("/steady/cavity/surface_z"), T = f.read("/steady/cavity/T");
  const double L = f.read("/grid/z").back() + 0.5 * (f.read("/grid/z")[1] - f.read("/grid/z")[0]);
  ASSERT_EQ(z.size(), T.size());
  ASSERT_GE(z.size(), 3u);
  const std::size_t rings = z.size() - 2;  // the back plate and the front annulus follow the rings
  std::printf("%zu surfaces: rings from %.4g to %.4g m, back plate %.4g m, annulus %.4g m (L = %.4g m)\n", z.size(),
              z[0], z[rings - 1], z[rings], z[rings + 1], L);
  for (std::size_t k = 0; k < rings; ++k) {
    EXPECT_GT(z[k], 0.0);
    EXPECT_LT(z[k], L);
    if (k > 0) {
      EXPECT_GT(z[k], z[k - 1]);
    }
  }
  EXPECT_NEAR(z[0] + z[rings - 1], L, 1e-9 * L);  // equal rings: symmetric centres
  EXPECT_EQ(z[rings], 0.0);
  EXPECT_NEAR(z[rings + 1], L, 1e-12 * L);
  EXPECT_EQ(f.string_attribute("/steady/cavity/surface_z", "units"), "m");
  std::filesystem::remove_all(dir);
}
