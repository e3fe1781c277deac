# Writes OUT (a header defining centrec's version string) from `git describe` of
# SOURCE_DIR at build time, touching OUT only when the string changes, so every build
# records the commit it was built from (a configure-time string went stale with each
# commit built without reconfiguring) and an unchanged tree rebuilds nothing.
execute_process(COMMAND git describe --always --dirty
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE git_version OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT git_version)
  set(git_version "unknown")
endif()
set(text "#pragma once\n// Written by cmake/write_version.cmake at build time.\n#define CENTREC_VERSION_STRING \"${PROJECT_VERSION}+${git_version}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
