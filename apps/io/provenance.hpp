#pragma once
// Provenance written as root attributes into every HDF5 output (docs/outputs.md): the code
// version, the case file, the resolved configuration and a hash of every input file, so a
// file found later says what made it.
#include <cstdint>
#include <string>
#include <vector>

#include "io/h5_file.hpp"

namespace centrec::io {

struct Provenance {
  std::string case_path;
  std::string resolved_config;           // the fully resolved YAML
  std::vector<std::string> input_files;  // the case file and the files it reads
};

// FNV-1a 64 of a byte string (also the DEM cache key's hash, runs/dem_cache.cpp).
std::uint64_t fnv1a64(const std::string& bytes);

// "fnv1a64:<16 hex digits>" of the file's bytes (FNV-1a 64), or "unreadable".
std::string file_hash(const std::string& path);

// Root attributes: code_version, case, resolved_config, input_hashes (one "<hash>  <path>"
// line per input file, as sha256sum prints them) and written_utc (ISO 8601).
void write_provenance(H5File& f, const Provenance& p);

}  // namespace centrec::io
