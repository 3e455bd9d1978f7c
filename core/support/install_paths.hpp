// Where sphkern finds its shipped data: next to the executable in a build tree, or
// under the install prefix.
#pragma once

#include <filesystem>

namespace sphkern {

std::filesystem::path executable_folder();

// A shipped data folder ("lattices", "studies", "reference"): the install prefix's
// share/sphkern/<name> if it exists, else the source tree's.
std::filesystem::path data_folder(const std::string& name);

} // namespace sphkern
