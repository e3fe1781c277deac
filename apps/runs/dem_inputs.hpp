#pragma once
// What a DEM computes from, as a resolved case records it: every scalar under the named
// sections as "section.key.subkey" -> value text, less the keys that choose how a DEM runs,
// not what it computes (thread count, progress and checkpoint intervals: the engine is
// bitwise the same at any thread count, docs/architecture.md "Threads and determinism").
// The DEM cache's key hashes these; `--dem-from` compares them key by key.
#include <initializer_list>
#include <map>
#include <string>

namespace centrec::runs {

std::map<std::string, std::string> dem_input_values(const std::string& resolved_yaml,
                                                    std::initializer_list<const char*> sections);

}  // namespace centrec::runs
