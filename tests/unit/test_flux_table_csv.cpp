// The flux table reader (apps/io/flux_table_csv.hpp): a table the thermal model can use is
// read as written; one it cannot (a number that is not finite, a flux no concentrator
// delivers, text after q or a third column, a table that ends before the film starts) is refused naming the
// file and the line (docs/reliability.md "Case files").
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/flux_table_csv.hpp"

using centrec::io::read_flux_table_csv;

namespace {
std::string write_table(const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / "centrec_flux_table_test.csv").string();
  std::ofstream(path, std::ios::trunc) << text;
  return path;
}

std::string refusal(const std::string& text) {
  std::vector<double> z, q;
  try {
    read_flux_table_csv(write_table(text), z, q);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FluxTableCsv, ReadsHeaderCommentsAndRowsAsWritten) {
  std::vector<double> z, q;
  read_flux_table_csv(write_table("z_m,q_W_m2\n# a comment\n-0.1, 0\n0.0, 1.5e6  # on the film\n0.5,2e6\n"), z, q);
  ASSERT_EQ(z.size(), 3u);
  EXPECT_EQ(z[0], -0.1);
  EXPECT_EQ(q[1], 1.5e6);
  EXPECT_EQ(z[2], 0.5);
  EXPECT_EQ(q[2], 2e6);
}

TEST(FluxTableCsv, RowsNoFilmCanHaveAreRefusedWithTheirLine) {
  struct Bad {
    const char* text;
    const char* line;
    const char* reason;
  };
  const std::vector<Bad> bad = {
      {"z,q\n0, 1e6\n0.5, inf\n", ":3:", "not finite"},
      {"0, 1e6\n0.5, nan\n", ":2:", "not finite"},
      {"0, 1e6\ninf, 1e6\n", ":2:", "not finite"},
      {"0, 1e6\n0.5, 1e300\n", ":2:", "above"},
      {"0, -5\n0.5, 1e6\n", ":1:", "negative"},
      {"0, 1e6\n0.5, 1e6 junk\n", ":2:", "q_W_m2 is not a number"},
      {"0, 1e6, 3\n0.5, 1e6\n", ":1:", "more than two columns"},
      {"-1.0, 1e6\n-0.5, 1e6\n", ":2:", "before the film starts"},
  };
  for (const Bad& b : bad) {
    const std::string msg = refusal(b.text);
    std::string shown = b.text;
    for (char& c : shown)
      if (c == '\n') c = '|';
    std::printf("%-28s -> %s\n", shown.c_str(), msg.c_str());
    EXPECT_NE(msg.find(b.line), std::string::npos) << b.text << " -> " << msg;
    EXPECT_NE(msg.find(b.reason), std::string::npos) << b.text << " -> " << msg;
  }
}
