# Writes build_info.cpp (cmake -P, at every build): the git description of the source
# tree, the build type and the compiler. configure_file leaves the file untouched when
# nothing changed, so only a new commit recompiles it.
# Variables: SOURCE_DIR, OUTPUT, BUILD_TYPE, COMPILER.
set(GIT_DESCRIBE "unknown")
find_program(GIT git)
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" describe --always --dirty --tags
    OUTPUT_VARIABLE described RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(status EQUAL 0 AND described)
    set(GIT_DESCRIBE "${described}")
  endif()
endif()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE "unknown")
endif()
file(WRITE "${OUTPUT}.in" [=[
// Written by share/cmake/BuildInfo.cmake at build time.
#include "support/io/build_info.hpp"

namespace sphkern::build_info {

const char* const git_describe = "@GIT_DESCRIBE@";
const char* const build_type = "@BUILD_TYPE@";
const char* const compiler = "@COMPILER@";

} // namespace sphkern::build_info
]=])
configure_file("${OUTPUT}.in" "${OUTPUT}" @ONLY)
