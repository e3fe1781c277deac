// Every repository path the docs and the code's comments cite exists (docs/conventions.md:
// comments cite the project's own files). Scanned: every Markdown file whole, and the
// comment text of C++ (after //), Python, YAML, CMake and shell files (after #), under the
// source folders and the top level. A cited path starts at one of the source folders, is
// not part of a longer path, and is checked as written, as a stem (apps/io/h5_file for
// apps/io/h5_file.hpp), relative to apps/ (the include root), with a shell brace list
// expanded (cases/d{12,17}.yaml) and a * matching anything in the file name. A path
// followed by < or $ is a pattern (slice_<NAME>.yaml, slice_dd$X.yaml) and is not checked.
// A Markdown link's local target is checked relative to its file's folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
const fs::path kRoot = CENTREC_SOURCE_DIR;
// The source folders, then apps/' own (cited relative to the include root apps/; a run's
// output folder is also called runs/..., so there only a source file counts as a citation).
const char* const kFolders[] = {"apps", "dem", "thermal", "coupling", "tests", "docs",  "cases",    "cmake",
                                ".ci",  "io",  "config",  "runs",     "cli",   "bench", "liggghts", "examples"};
const int kSourceFolders = 9;  // the first nine are scanned

bool path_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '/' || c == '-' || c == '*' ||
         c == '{' || c == '}' || c == ',';
}

// A name with * against a pattern (a * matches any run of characters).
bool glob_match(const std::string& p, const std::string& s) {
  if (p.empty()) return s.empty();
  if (p[0] == '*') return glob_match(p.substr(1), s) || (!s.empty() && glob_match(p, s.substr(1)));
  return !s.empty() && p[0] == s[0] && glob_match(p.substr(1), s.substr(1));
}

bool exists_as_cited(const fs::path& base, const std::string& cited) {
  const fs::path p = base / cited;
  const std::string name = p.filename().string();
  const fs::path dir = p.parent_path();
  if (name.find('*') == std::string::npos && fs::exists(p)) return true;
  if (!fs::is_directory(dir)) return false;
  const std::string pattern = name.find('*') == std::string::npos ? name + ".*" : name;  // else a stem
  for (const auto& e : fs::directory_iterator(dir))
    if (glob_match(pattern, e.path().filename().string())) return true;
  return false;
}

std::vector<std::string> expand_braces(const std::string& s) {
  const auto open = s.find('{'), close = s.find('}');
  if (open == std::string::npos || close == std::string::npos || close < open) return {s};
  std::vector<std::string> out;
  const std::string head = s.substr(0, open), tail = s.substr(close + 1), list = s.substr(open + 1, close - open - 1);
  std::size_t from = 0;
  while (from <= list.size()) {
    const auto comma = std::min(list.find(',', from), list.size());
    for (const auto& rest : expand_braces(tail)) out.push_back(head + list.substr(from, comma - from) + rest);
    from = comma + 1;
  }
  return out;
}

bool source_file(const std::string& p) {
  for (const char* e : {".cpp", ".hpp", ".py"})
    if (p.size() > std::strlen(e) && p.compare(p.size() - std::strlen(e), std::strlen(e), e) == 0) return true;
  return false;
}

// The repository paths cited in one line of text.
std::vector<std::string> cited_paths(const std::string& text) {
  std::vector<std::string> out;
  for (int k = 0; k < static_cast<int>(std::size(kFolders)); ++k) {
    const std::string lead = std::string(kFolders[k]) + "/";
    for (auto at = text.find(lead); at != std::string::npos; at = text.find(lead, at + 1)) {
      if (at > 0 && (path_char(text[at - 1]) || text[at - 1] == '~')) continue;  // inside a longer path
      std::size_t end = at + lead.size();
      while (end < text.size() && path_char(text[end])) ++end;
      std::string p = text.substr(at, end - at);
      while (!p.empty() && (p.back() == '.' || p.back() == ',' || p.back() == '/')) p.pop_back();
      if (p.size() <= lead.size()) continue;                                      // the folder alone
      if (end < text.size() && (text[end] == '<' || text[end] == '$')) continue;  // a pattern
      if (k >= kSourceFolders && !source_file(p)) continue;
      for (const auto& e : expand_braces(p)) out.push_back(e);
    }
  }
  return out;
}

// The local targets of a Markdown line's links [text](target), without #anchor.
std::vector<std::string> markdown_links(const std::string& line) {
  std::vector<std::string> out;
  for (auto at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
    const auto end = line.find(')', at + 2);
    if (end == std::string::npos) break;
    std::string t = line.substr(at + 2, end - at - 2);
    t = t.substr(0, t.find('#'));
    if (t.empty() || t.find("://") != std::string::npos || t.rfind("mailto:", 0) == 0 ||
        t.find(' ') != std::string::npos)
      continue;
    out.push_back(t);
  }
  return out;
}

// The text of a line that may cite paths: a Markdown line whole, a code line's comment.
std::string citing_text(const fs::path& file, const std::string& line) {
  const std::string ext = file.extension().string();
  if (ext == ".md") return line;
  const std::string mark = (ext == ".cpp" || ext == ".hpp" || ext == ".h") ? "//" : "#";
  if (mark == "#" && line.find("#include") != std::string::npos) return "";
  const auto at = line.find(mark);
  return at == std::string::npos ? "" : line.substr(at);
}

bool scanned(const fs::path& f) {
  static const char* const exts[] = {".md", ".cpp", ".hpp", ".h", ".py", ".yaml", ".txt", ".sh", ".cmake"};
  const std::string ext = f.extension().string();
  for (const char* e : exts)
    if (ext == e) return true;
  return f.filename() == "run" || f.filename() == "setup.sh";
}
}  // namespace

TEST(CitedPaths, EveryRepositoryPathCitedInDocsAndCommentsExists) {
  std::vector<fs::path> files = {kRoot / "README.md", kRoot / "CMakeLists.txt", kRoot / "setup.sh"};
  for (int k = 0; k < kSourceFolders; ++k) {
    const char* folder = kFolders[k];
    if (!fs::is_directory(kRoot / folder)) continue;
    for (const auto& e : fs::recursive_directory_iterator(kRoot / folder))
      if (e.is_regular_file() && scanned(e.path())) files.push_back(e.path());
  }
  int checked = 0;
  std::string missing;
  for (const auto& file : files) {
    std::ifstream in(file);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      const std::string where = "  (cited at " + fs::relative(file, kRoot).string() + ":" + std::to_string(n) + ")\n";
      for (const std::string& p : cited_paths(citing_text(file, line))) {
        ++checked;
        if (!exists_as_cited(kRoot, p) && !exists_as_cited(kRoot / "apps", p)) missing += "  " + p + where;
      }
      if (file.extension() != ".md") continue;
      for (const std::string& p : markdown_links(line)) {  // relative to the file's folder
        ++checked;
        if (!fs::exists(file.parent_path() / p)) missing += "  " + p + where;
      }
    }
  }
  std::printf("%zu files scanned, %d cited paths checked\n%s", files.size(), checked, missing.c_str());
  EXPECT_GT(checked, 500);  // the scan finds the citations (a broken scan finds none)
  EXPECT_TRUE(missing.empty()) << "cited paths that do not exist:\n" << missing;
}

TEST(CitedPaths, TheScanFindsWhatACitationLooksLike) {
  const auto p = cited_paths(
      "see dem/contact_law.hpp:61, docs/a.md. and lammps/dem/x.cpp cases/d{12,17}.yaml "
      "cases/r/slice_<NAME>.yaml runs/dd80 runs/dem_run.cpp");
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0], "dem/contact_law.hpp");  // the line number is not part of it
  EXPECT_EQ(p[1], "docs/a.md");
  EXPECT_EQ(p[2], "cases/d12.yaml");
  EXPECT_EQ(p[3], "cases/d17.yaml");
  EXPECT_EQ(p[4], "runs/dem_run.cpp");                     // apps/runs/; runs/dd80 is a run's folder
  EXPECT_TRUE(exists_as_cited(kRoot, "dem/contact_law"));  // a stem
  EXPECT_TRUE(exists_as_cited(kRoot, "apps/io/*.cpp"));
  EXPECT_FALSE(exists_as_cited(kRoot, "dem/no_such_file.hpp"));
  const auto links = markdown_links("[a](outputs.md#dem-h5), [b](https://x.org/y.md), [c](scale_down/table.csv)");
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(links[0], "outputs.md");
  EXPECT_EQ(links[1], "scale_down/table.csv");
}
