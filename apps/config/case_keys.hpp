#pragma once
// The case-key reference (docs/case_keys.md): every YAML key of a case file with its type,
// default, allowed range or choices, unit and meaning, recorded from the section readers
// themselves as they read a set of small cases that together reach every branch, so the
// reference cannot drift from what is read (docs/conventions.md, "Case files").
#include <string>
#include <vector>

#include "config/strict_yaml.hpp"

namespace centrec::config {

// Every key the readers read, in reading order, each path once; a key first read only in
// a case that takes a branch carries that branch in `when` (e.g. "thermal.flux.profile: gaussian").
struct ReferencedKey {
  KeyRecord key;
  std::string when;
};
std::vector<ReferencedKey> case_keys();

// The Markdown of docs/case_keys.md for these keys. Throws std::logic_error naming a key
// whose reader gives no meaning (add it at the reader).
std::string case_keys_markdown(const std::vector<ReferencedKey>& keys);

}  // namespace centrec::config
