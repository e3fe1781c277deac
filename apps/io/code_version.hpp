#pragma once
// centrec's version, "<project version>+<git describe --always --dirty>" of the tree this
// binary was built from; written into every output and into the DEM cache key.
namespace centrec::io {

const char* code_version();

}  // namespace centrec::io
