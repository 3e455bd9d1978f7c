#include "support/install_paths.hpp"

#include <system_error>

#ifndef SPHKERN_SOURCE_DIR
#define SPHKERN_SOURCE_DIR "."
#endif

namespace sphkern {
namespace fs = std::filesystem;

fs::path executable_folder()
{
    std::error_code ec;
    auto exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::current_path() : exe.parent_path();
}

fs::path data_folder(const std::string& name)
{
    std::error_code ec;
    auto installed = executable_folder().parent_path() / "share" / "sphkern" / name;
    if (fs::is_directory(installed, ec)) return installed;
    fs::path source(SPHKERN_SOURCE_DIR);
    // lattices/ sits at the top of the source tree; studies and reference data under share/.
    if (fs::is_directory(source / name, ec)) return source / name;
    return source / "share" / name;
}

} // namespace sphkern
