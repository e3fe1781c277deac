#include "io/atomic_write.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace centrec::io {

void write_text_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f << text;
    f.flush();
    if (!f) throw std::runtime_error("error writing " + tmp);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot create output directory " + dir + (ec ? ": " + ec.message() : ""));
}

std::string file_checksum(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::uint64_t h = 1469598103934665603ULL;
  std::vector<char> buf(1 << 16);
  while (f.read(buf.data(), static_cast<std::streamsize>(buf.size())) || f.gcount() > 0) {
    const auto n = static_cast<std::size_t>(f.gcount());
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ULL;
  }
  if (f.bad()) throw std::runtime_error("error reading " + path);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

namespace {
// The absolute, normal form of a folder path, without a trailing separator.
std::filesystem::path absolute_folder(const std::string& dir) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(dir, ec).lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  return p;
}
}  // namespace

OutputFolder::OutputFolder(std::string dir) : dir_(std::move(dir)) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The top-most missing folder, removed again if the run leaves it empty.
  fs::path p = absolute_folder(dir_);
  while (!p.empty() && !fs::exists(p, ec) && p.has_parent_path() && p.parent_path() != p) {
    created_ = p.string();
    p = p.parent_path();
  }
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw std::runtime_error("cannot write to " + dir_ + ": it exists and is not a folder");
  ensure_directory(dir_);
  const std::string probe = dir_ + "/.centrec-write-test." + std::to_string(::getpid());
  {
    std::ofstream f(probe, std::ios::binary | std::ios::trunc);
    f << "x";
    f.flush();
    if (!f) {
      fs::remove(probe, ec);
      throw std::runtime_error("cannot write to the output folder " + dir_ + " (permissions or a full disk?)");
    }
  }
  fs::remove(probe, ec);
}

OutputFolder::~OutputFolder() {
  if (created_.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  // Remove empty folders from the output folder up to the top-most one created here.
  for (fs::path p = absolute_folder(dir_); !p.empty(); p = p.parent_path()) {
    if (!fs::is_directory(p, ec) || !fs::is_empty(p, ec)) break;
    fs::remove(p, ec);
    if (p.string() == created_ || ec) break;
  }
}

}  // namespace centrec::io
