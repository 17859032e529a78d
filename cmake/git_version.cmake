# Writes OUT, a header with the project's version and the git description of the source tree
# (`git describe --always --dirty --tags`), at every build; the file is rewritten only when its
# text changes, so nothing rebuilds for nothing. Without git or outside a clone (a source
# tarball, a Debian build) the description is PARSONS_GIT_DESCRIPTION from the environment if
# set, else "no git description".
#   cmake -DSRC=<source dir> -DOUT=<header> -DVERSION=<x.y.z> -P git_version.cmake
set(description "")
find_program(GIT git)
if(GIT AND EXISTS "${SRC}/.git")
  execute_process(COMMAND "${GIT}" -C "${SRC}" describe --always --dirty --tags
                  OUTPUT_VARIABLE description OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET RESULT_VARIABLE failed)
  if(failed)
    set(description "")
  endif()
endif()
if(description STREQUAL "" AND DEFINED ENV{PARSONS_GIT_DESCRIPTION})
  set(description "$ENV{PARSONS_GIT_DESCRIPTION}")
endif()
if(description STREQUAL "")
  set(description "no git description")
endif()
string(REPLACE "\\" "\\\\" description "${description}")
string(REPLACE "\"" "\\\"" description "${description}")
set(text "// Written by cmake/git_version.cmake at build time; do not edit.
#pragma once
#define PARSONS_VERSION_NUMBER \"${VERSION}\"
#define PARSONS_GIT_DESCRIPTION \"${description}\"
")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
