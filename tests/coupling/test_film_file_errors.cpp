// A corrupted or mismatched film-field file gives a clear error naming the file and what is
// wrong, both when read directly and through a case's `film.file`.
#include <gtest/gtest.h>

#include "tests/test_case_dir.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include "config/case_thermal.hpp"
#include "coupling/film_mapping.hpp"
#include "io/film_field_h5.hpp"
#include "io/h5_file.hpp"
#include "synthetic_dem_film.hpp"

using namespace centrec;
namespace fs = std::filesystem;

namespace {

thermal::FilmField good_film() { return coupling::map_dem_film(test::synthetic_dem_film(0.12)).film; }

void write(const std::string& path, const thermal::FilmField& f) {
  io::H5File h = io::H5File::create(path);
  io::write_film_field(h, f);
  h.commit();
}

std::string read_error(const std::string& path) {
  try {
    io::read_film_field(io::H5File::open_read(path));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string case_error(const std::string& dir, const std::string& film_path) {
  const std::string yaml = dir + "/case.yaml";
  std::ofstream(yaml) << "film: {file: " << film_path << "}\nthermal: {grid: {nz: 10, nxi: 4}}\n";
  try {
    config::read_thermal_case(yaml);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FilmFileErrors, CorruptedFileNamesTheFile) {
  const std::string dir = centrec::testing::temp_dir("film_errors"), path = dir + "/film.h5";
  write(path, good_film());
  // Overwrite the middle of the file with garbage (a truncated copy or a disk error).
  const auto size = fs::file_size(path);
  fs::resize_file(path, size / 3);
  const std::string e = read_error(path);
  std::printf("corrupted: %s\n", e.c_str());
  EXPECT_NE(e.find(path), std::string::npos);
  const std::string c = case_error(dir, path);
  std::printf("through a case: %s\n", c.c_str());
  EXPECT_NE(c.find("film.file"), std::string::npos);
  EXPECT_NE(c.find(path), std::string::npos);
  fs::remove_all(dir);
}

TEST(FilmFileErrors, MismatchedShapesAndParticlesAreRefused) {
  const std::string dir = centrec::testing::temp_dir("film_errors");
  thermal::FilmField f = good_film();
  // u written for one wall-distance point fewer than eta has.
  {
    io::H5File h = io::H5File::create(dir + "/shape.h5");
    h.create_group("/film");
    h.write("/film/z", f.z, "m");
    h.write("/film/eta", f.eta, "m");
    h.write("/film/t", f.t, "m");
    const std::size_t nz = f.nz(), ne = f.neta() - 1;
    std::vector<double> u(nz * ne, 0.1);
    h.write("/film/u", u, {nz, ne}, "m/s");
    h.write("/film/phi", u, {nz, ne}, "1");
    h.write("/film/D", u, {nz, ne}, "m2/s");
    h.commit();
  }
  const std::string shape = read_error(dir + "/shape.h5");
  std::printf("shape: %s\n", shape.c_str());
  EXPECT_NE(shape.find("/film/u must have shape [nz, neta]"), std::string::npos);
  // Thickness beyond the last wall-distance point: inconsistent contents.
  thermal::FilmField thick = f;
  thick.t[3] = 2.0 * thick.eta.back();
  write(dir + "/thick.h5", thick);
  const std::string t = read_error(dir + "/thick.h5");
  std::printf("thickness: %s\n", t.c_str());
  EXPECT_NE(t.find("thickness exceeds"), std::string::npos);
  // A film of other particles than the case's thermal material.
  thermal::FilmField other = f;
  other.particle_diameter = 2.0e-3;
  write(dir + "/other.h5", other);
  const std::string m = case_error(dir, dir + "/other.h5");
  std::printf("particles: %s\n", m.c_str());
  EXPECT_NE(m.find("mismatched film file"), std::string::npos);
  // No film group at all.
  const std::string none = case_error(dir, dir + "/shape.h5x");
  EXPECT_NE(none.find("film.file"), std::string::npos);
  fs::remove_all(dir);
}
