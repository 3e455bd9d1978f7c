#include "support/io/install_paths.hpp"

#include <system_error>

#ifndef SPHKERN_SOURCE_DIR
#define SPHKERN_SOURCE_DIR "."
#endif
#ifndef SPHKERN_INSTALL_LIBDIR
#define SPHKERN_INSTALL_LIBDIR "lib"
#endif
#ifndef SPHKERN_INSTALL_DATADIR
#define SPHKERN_INSTALL_DATADIR "share"
#endif

namespace sphkern {
namespace fs = std::filesystem;

namespace {

fs::path home_build, home_prefix; // set by set_home

} // namespace

fs::path executable_folder()
{
    std::error_code ec;
    auto exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::current_path() : exe.parent_path();
}

void set_home(const fs::path& build_folder, const fs::path& install_prefix)
{
    home_build = build_folder;
    home_prefix = install_prefix;
}

namespace {

fs::path build_home() { return home_build.empty() ? executable_folder() : home_build; }
fs::path prefix_home() { return home_prefix.empty() ? executable_folder().parent_path() : home_prefix; }

} // namespace

std::vector<fs::path> shipped_plugin_folders()
{
    std::vector<fs::path> folders = {build_home() / "plugins",
                                     prefix_home() / SPHKERN_INSTALL_LIBDIR / "sphkern" / "plugins"};
    if (fs::path(SPHKERN_INSTALL_LIBDIR) != "lib") folders.push_back(prefix_home() / "lib" / "sphkern" / "plugins");
    return folders;
}

fs::path data_folder(const std::string& name)
{
    std::error_code ec;
    auto installed = prefix_home() / SPHKERN_INSTALL_DATADIR / "sphkern" / name;
    if (fs::is_directory(installed, ec)) return installed;
    fs::path source(SPHKERN_SOURCE_DIR);
    // lattices/ sits at the top of the source tree; studies and reference data under share/.
    if (fs::is_directory(source / name, ec)) return source / name;
    return source / "share" / name;
}

} // namespace sphkern
