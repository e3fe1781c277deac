#include "io/code_version.hpp"

#include "centrec_version.hpp"  // generated at build time (cmake/write_version.cmake)

namespace centrec::io {

const char* code_version() { return CENTREC_VERSION_STRING; }

}  // namespace centrec::io
