// What the build knows of itself; build_info.cpp is written by the build (share/cmake/BuildInfo.cmake).
#pragma once

namespace sphkern::build_info {

extern const char* const git_describe; // `git describe --always --dirty` of the source tree, or "unknown"
extern const char* const build_type;   // CMAKE_BUILD_TYPE
extern const char* const compiler;     // compiler id and version

} // namespace sphkern::build_info
