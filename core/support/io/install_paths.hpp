// Where sphkern finds its plugins and shipped data. A program (the command line, or the
// Python module) has a home folder: the build folder in a build tree (plugins in
// <home>/plugins), or the install prefix's bindir, whose parent is the prefix (plugins in
// <prefix>/<libdir>/sphkern/plugins, data in <prefix>/<datadir>/sphkern, with libdir and
// datadir as configured by GNUInstallDirs, multiarch included).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// The command line's home is its executable's folder; the Python module sets its own.
std::filesystem::path executable_folder();
void set_home(const std::filesystem::path& build_folder, const std::filesystem::path& install_prefix);

// Plugin folders that may exist, in search order (without SPHKERN_PLUGIN_PATH).
std::vector<std::filesystem::path> shipped_plugin_folders();

// A shipped data folder ("lattices", "studies", "reference"): the install prefix's
// <datadir>/sphkern/<name> if it exists, else the source tree's.
std::filesystem::path data_folder(const std::string& name);

} // namespace sphkern
